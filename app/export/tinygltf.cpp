// tinygltf's implementation, compiled once here (Debian's README.Debian of libtinygltf-dev: define
// TINYGLTF_IMPLEMENTATION in exactly one file), with export/tinygltf.h's macros, rather than
// linking Debian's libtinygltf.so, which was built with its image loaders.
#define TINYGLTF_IMPLEMENTATION
#include "export/tinygltf.h"
