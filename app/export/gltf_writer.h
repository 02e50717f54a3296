#pragma once
// The glTF 2.0 model of a run (Khronos glTF 2.0.1): one node per track (gltf_track.h), named as
// the body, holding the mesh of its shape and colour; one animation moving every node at the
// frame times. The model goes to a file through tinygltf's own writer (gltf_file.h).
//
// Layout: one buffer; one buffer view per accessor. Bodies sharing a mesh and a colour (a spawn
// block's) share one glTF mesh; bodies sharing a mesh share its vertex arrays. The scene's static
// planes are left out: the renderer draws none either (its ground is view.grid's grid at y = 0),
// and a viewer shows its own ground. World coordinates go as they are: glTF's are metres, +Y up,
// right-handed (3.4 "Coordinate System and Units"), as the shipped scenes' are (gravity -y).
#include <string>

#include "export/gltf_track.h"
#include "export/tinygltf.h"

namespace rbsim::app {

// glTF 2.0, 3.9.2: metallicFactor defaults to 1, a metal; the renderer's bodies are dielectric.
inline constexpr double kGltfMetallic = 0.0;  // [1]
// The renderer's highlight is Blinn-Phong with exponent 40 (shaders/lighting.glsl), about GGX's
// alpha = sqrt(2 / (40 + 2)) = 0.22, and glTF's roughness is sqrt(alpha).
inline constexpr double kGltfRoughness = 0.47;  // [1]

// `fps` spaces the keys (key k at k / fps seconds); `title` names the scene and the animation.
// The track must hold at least one body and one frame.
tinygltf::Model buildGltfModel(const GltfTrack& track, double fps, const std::string& title);

}  // namespace rbsim::app
