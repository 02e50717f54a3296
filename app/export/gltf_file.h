#pragma once
// Where a run's glTF goes (--gltf FILE): the format its name asks for, what it may cost, and the
// file itself. tinygltf serialises the model (TinyGLTF::WriteGltfSceneToStream, buffers embedded)
// into a CheckedFile rather than through its WriteGltfSceneToFile, whose std::ofstream writes go
// unchecked (tinygltf 2.7: "TODO: Check error on stream.write"): a full disk must stop the run
// with the file and the OS's reason, as every other output does (render/checked_file.h).
#include <cstdint>
#include <string>

#include "export/gltf_track.h"
#include "render/checked_file.h"

namespace rbsim::app {

enum class GltfFormat {
  Binary,  // .glb: a JSON chunk and a BIN chunk in one file (glTF 2.0, 4 "GLB File Format")
  Json,    // .gltf: JSON, the buffer inside as a base64 data: URI (3.6.1.1), a third larger
};

// The format a file name asks for, by its extension in any case; throws InputError ("--gltf
// NAME") for any other name.
GltfFormat gltfFormatOf(const std::string& path);

// Keys an animation may have: as many frames as a video may (run/output_budget.h), 9.3 h at 30
// fps. Their float32 times k / fps stay strictly increasing, as animation.sampler.input requires
// (time[n + 1] > time[n]), up to 2^23 keys, far beyond.
inline constexpr std::uint64_t kMaxGltfFrames = 1'000'000;  // [frames]
// A file's size: a .glb's header holds its length as a uint32 (4 "GLB File Format", 4.29 GB), and
// tinygltf holds the buffer about three times in memory while it writes (the model's, the BIN
// chunk's copy, the JSON's base64 for .gltf).
inline constexpr double kMaxGltfBytes = 1e9;  // [B]
// What one body adds per frame at least: its translation (3 floats) and rotation (4 floats).
inline constexpr double kGltfBytesPerBodyFrame = 28.0;  // [B]

// Throws InputError(file, "--gltf", ...) with the estimate and the limit when `frames` frames of
// up to `bodies` bodies at once (Scene::mostBodiesAtOnce) pass kMaxGltfFrames or kMaxGltfBytes.
// `file` is the scene's.
void checkGltfBudget(const std::string& file, std::uint64_t frames, double bodies);

class GltfFile {
 public:
  // Creates the file (and the folders above it) now, so that a place that cannot be written
  // fails before the run. Throws InputError (field --gltf), also for a name gltfFormatOf refuses.
  explicit GltfFile(const std::string& path);
  // Writes the model of `track` (gltf_writer.h) and closes the file; throws InputError naming
  // the file and the OS's reason when a write fails.
  void write(const GltfTrack& track, double fps, const std::string& title);
  const std::string& path() const { return path_; }

 private:
  [[noreturn]] void fail() const;

  std::string path_;
  GltfFormat format_;
  render::CheckedFile out_;
};

}  // namespace rbsim::app
