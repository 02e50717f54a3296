#pragma once
// tinygltf (Debian's libtinygltf-dev 2.7, one header) as every file of rbsim includes it: the
// macros below change inline members of its TinyGLTF class, so they must be the same in every
// file, and only this header sets them. rbsim writes no images, so neither stb_image nor
// stb_image_write is compiled in, and no image file is ever read.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
