#include "export/gltf_file.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <system_error>

#include "export/gltf_writer.h"
#include "export/tinygltf.h"
#include "rbsim/io/input_error.h"

namespace rbsim::app {

namespace {

// The std::ostream tinygltf writes to, passing every byte on to a CheckedFile (which keeps the
// first failure and its reason); a failed write also sets the stream's badbit.
class CheckedFileBuffer : public std::streambuf {
 public:
  explicit CheckedFileBuffer(render::CheckedFile& file) : file_(file) {}

 protected:
  std::streamsize xsputn(const char* bytes, std::streamsize count) override {
    return file_.write(bytes, static_cast<std::size_t>(count)) ? count : 0;
  }
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char byte = traits_type::to_char_type(c);
    return file_.write(&byte, 1) ? c : traits_type::eof();
  }

 private:
  render::CheckedFile& file_;
};

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

}  // namespace

GltfFormat gltfFormatOf(const std::string& path) {
  const std::string extension = lowerCase(std::filesystem::path(path).extension().string());
  if (extension == ".glb") return GltfFormat::Binary;
  if (extension == ".gltf") return GltfFormat::Json;
  throw InputError("", "--gltf " + path,
                   "expected a file name ending in .glb (binary glTF 2.0) or .gltf (glTF 2.0 JSON, its buffer embedded)");
}

void checkGltfBudget(const std::string& file, std::uint64_t frames, double bodies) {
  char text[160];
  if (frames > kMaxGltfFrames) {
    std::snprintf(text, sizeof text, "%llu frames are more than an animation may have (%llu): lower view.fps (--fps) or run fewer steps",
                  static_cast<unsigned long long>(frames), static_cast<unsigned long long>(kMaxGltfFrames));
    throw InputError(file, "--gltf", text);
  }
  const double bytes = static_cast<double>(frames) * bodies * kGltfBytesPerBodyFrame;
  if (bytes <= kMaxGltfBytes) return;
  std::snprintf(text, sizeof text, "%llu frames of up to %.6g bodies need at least %.3g bytes (%g a body a frame); the limit is %.3g: "
                "lower view.fps (--fps) or run fewer steps",
                static_cast<unsigned long long>(frames), bodies, bytes, kGltfBytesPerBodyFrame, kMaxGltfBytes);
  throw InputError(file, "--gltf", text);
}

GltfFile::GltfFile(const std::string& path) : path_(path), format_(gltfFormatOf(path)) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (ec) throw InputError(path, "--gltf", "cannot create the glTF file's folder (" + ec.message() + ")");
  if (!out_.open(path)) throw InputError(path, "--gltf", "cannot create the glTF file (" + out_.error() + ")");
}

void GltfFile::fail() const {
  throw InputError(path_, "--gltf", "cannot write the glTF file (" + out_.error() + ")");
}

void GltfFile::write(const GltfTrack& track, double fps, const std::string& title) {
  const tinygltf::Model model = buildGltfModel(track, fps, title);
  CheckedFileBuffer buffer(out_);
  std::ostream stream(&buffer);
  tinygltf::TinyGLTF writer;
  const bool binary = format_ == GltfFormat::Binary;
  const bool written = writer.WriteGltfSceneToStream(&model, stream, /*prettyPrint=*/false, /*writeBinary=*/binary);
  if (!out_.close()) fail();
  // tinygltf returns false only over images, which rbsim never writes: not the user's doing.
  if (!written) throw std::runtime_error("tinygltf could not serialise the glTF model of " + path_);
}

}  // namespace rbsim::app
