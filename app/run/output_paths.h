#pragma once
// Outputs never touch inputs (issue 37). Before anything is written, every output file (--trace,
// --record, --video, --screenshot) is compared with every input (the scene files, the meshes they
// read, the recording replayed) and with every other output: by file identity (device and inode,
// so a hard link or a symlink is caught) where the file exists, by its canonical path where it
// does not yet. An output that exists and is not a regular file (a FIFO, whose open() would block
// for ever; a device; a folder) is refused, and so is a --frames path that is not a folder.
#include <cstddef>
#include <string>
#include <vector>

namespace rbsim::app {

struct NamedFile {
  std::string role;  // how the user named it: "--trace", "scene", "mesh", "recording"
  std::string path;
};

// Throws InputError (exit 2) naming both files of the first clash, or the output that is not a
// regular file.
void checkOutputPaths(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs,
                      const std::string& framesDir);

// Removes the frames of an earlier run from a --frames folder: the files named exactly as this
// run names its frames (frame_NNNNNN.png, render/png_sequence_writer.h), nothing else, so that a
// shorter run does not leave the old run's last frames after its own. Returns how many.
std::size_t removeOldFrames(const std::string& framesDir);

// Throws InputError unless `path` is an existing regular file (a FIFO given as a recording would
// block the reader's open() for ever).
void requireRegularInput(const NamedFile& input, const std::string& kind);

}  // namespace rbsim::app
