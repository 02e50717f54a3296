#pragma once
// A recording of a run (`--record FILE`, issue 24): the scenes it ran and every step's state, so
// `rbsim replay FILE` draws it again, with another camera, size or overlay, without simulating
// (Jolt's StateRecorder; deterministic replay is a standing request to Box2D, Rapier and bepu).
//
// The file, little-endian:
//   "RBSIMREC", u32 kRecordingVersion, u64 n, n bytes of header JSON (rbsim's version, the
//   overrides, each phase's scene file text, name and absolute folder, and every other file it
//   read with its size and CRC-32), u32 CRC-32 of those n bytes (an edited mass is refused);
//   blocks of entries: u32 raw size, u32 deflated size, u32 CRC-32 of the deflated bytes, the bytes
//   deflated by libdeflate; the last block is empty (raw size 0) and its CRC field is the number
//   of entries, so a file cut short anywhere is known to be.
// An entry is one world after one step (record/entry_codec.h): its bodies', particles', soft
// bodies' and 2D bodies' states, and at a step that changed the set of bodies (spawned, removed,
// broken) a World snapshot from which a replay makes the same bodies.
#include <cstdint>
#include <cstdio>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "rbsim/world/world.h"

namespace rbsim::app {

// 2: the header's checksum, absolute folders and the files' checksums (issue 37).
// 3: entries carry a World snapshot where the set of bodies changed, and the 2D bodies (issue 58).
inline constexpr std::uint32_t kRecordingVersion = 3;
// Entries read ahead of the world that is waiting for its own, at most (a compared phase
// replayed at another frame rate reads a frame's steps of the others ahead; a damaged or forged
// file could ask for the whole file).
inline constexpr std::size_t kMaxPendingBytes = std::size_t{256} << 20;  // [bytes]
// The worlds a recording's entries may name: a compared run's (run/phase.h kMaxComparedWorlds,
// which run/runner.cpp asserts fits); an entry naming another is damage.
inline constexpr std::size_t kMaxRecordedWorlds = 8;

// A file a scene read besides itself (a mesh), as it was when recorded.
struct RecordedFile {
  std::string path;  // as the scene resolved it, absolute
  std::uint64_t bytes = 0;
  std::uint32_t crc32 = 0;
};
// The file's size and CRC-32 now; InputError naming it when it cannot be read or is not a
// regular file.
RecordedFile recordedFileOf(const std::string& path);

struct RecordedPhase {
  std::string file;     // as the run named it, for messages
  std::string baseDir;  // where its mesh paths start, absolute: a replay works from any folder
  std::string text;     // the scene file as it was read
  std::vector<RecordedFile> files;  // meshes it read
};

struct RecordingHeader {
  std::string rbsimVersion;
  std::string title;                   // the overlay's heading (a demo's), empty for a scene's own
  std::vector<std::string> overrides;  // --set assignments (and flags turned into them)
  std::vector<RecordedPhase> phases;
};

class RecordWriter {
 public:
  // Throws InputError (field --record) when the file cannot be created or written.
  RecordWriter(const std::string& path, const RecordingHeader& header);
  ~RecordWriter();
  RecordWriter(const RecordWriter&) = delete;
  RecordWriter& operator=(const RecordWriter&) = delete;

  // After each step of world `world`. Throws InputError when the step changed the set of bodies
  // of a World that cannot be saved as a snapshot (world_snapshot.h: step listeners, lcp), which
  // the runner refuses before the run (runner.cpp recordingHeader).
  void write(std::size_t world, const World& state);
  void close();  // the last block and the end; InputError when a write fails

  std::uint64_t entries() const { return entries_; }
  std::uint64_t bodySteps() const { return bodySteps_; }  // rigid and 2D bodies x steps
  std::uint64_t fileBytes() const { return fileBytes_; }
  std::uint64_t snapshots() const { return snapshots_; }  // entries with a World snapshot

 private:
  void flush();
  void put(const void* data, std::size_t bytes);

  std::string path_;
  std::string partial_;  // what is written: path_ + ".partial", renamed by close(); path_ for a device
  std::FILE* file_ = nullptr;
  std::vector<std::uint8_t> raw_;
  std::vector<std::uint8_t> deflated_;
  void* compressor_ = nullptr;
  std::uint64_t entries_ = 0, bodySteps_ = 0, fileBytes_ = 0, snapshots_ = 0;
  std::vector<std::size_t> fractures_;  // per world: World::fractureEvents() at its last entry
};

// An entry kept to show again (the replay window's timeline): its state, and the World snapshot
// of the last change of bodies before it with the scene's World to read it against (shared by
// the frames between two changes; none while the bodies are the scene's own).
struct KeptEntry {
  std::vector<std::uint8_t> state;  // an entry without its snapshot
  std::shared_ptr<const std::vector<std::uint8_t>> bodySet;
  std::shared_ptr<const World> base;
  bool empty() const { return state.empty(); }
};

class RecordReader {
 public:
  // Throws InputError naming the file: unreadable, not a recording, another format version or
  // rbsim version, a header that does not parse.
  explicit RecordReader(const std::string& path);
  ~RecordReader();
  RecordReader(const RecordReader&) = delete;
  RecordReader& operator=(const RecordReader&) = delete;

  const RecordingHeader& header() const { return header_; }
  const std::string& path() const { return path_; }
  // InputError unless every file phase `phase` of the recording read is as it was (a mesh changed
  // since would be drawn at the old poses).
  void checkFiles(std::size_t phase) const;
  // Puts the next entry into `world`, which must be world `index` of the replayed phase's
  // `worldCount` and hold the bodies, particle systems and soft bodies of the recording's.
  // InputError when the file ends (truncated), a block is damaged, the entry is of another world
  // or shape, a state is not finite or not a unit quaternion, or entries of other worlds run more
  // than kMaxPendingBytes ahead.
  void restoreNext(std::size_t index, std::size_t worldCount, World& world);
  // Whether world `index`'s set of bodies has changed since its phase began (an entry with a
  // World snapshot was restored): its bodies are no longer the scene's.
  bool bodiesChanged(std::size_t index) const { return index < bodySets_.size() && bodySets_[index] != nullptr; }
  // InputError unless the recording ends here, with as many entries as were read.
  void expectEnd();
  // The entry restoreNext restored last, to keep (the replay window keeps one per frame to scrub
  // back and forth), and puts such a kept entry of world `index` into `world` again (a World of
  // the same scene, at any step).
  KeptEntry lastEntry() const;
  void restore(const KeptEntry& entry, std::size_t index, World& world);

 private:
  bool loadBlock();  // false at the end marker
  // entry_ into `world`; with nextStep, it must be the step after the world's. An entry with a
  // World snapshot replaces `world` by the snapshot read against the scene's World (bases_).
  void restoreEntry(std::size_t index, World& world, bool nextStep);
  [[noreturn]] void fail(const std::string& problem) const;
  std::uint64_t remainingBytes() const;  // in the file after the read position

  std::string path_;
  std::uintmax_t fileBytes_ = 0;  // its size when opened
  // Owned from the moment it opens: a constructor that refuses the file still closes it (the
  // recording fuzzer ran out of file descriptors after 61,525 refused inputs).
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_{nullptr, &std::fclose};
  RecordingHeader header_;
  std::vector<std::uint8_t> block_;
  std::size_t offset_ = 0;
  std::vector<std::deque<std::vector<std::uint8_t>>> pending_;  // per world: entries read ahead
  std::size_t pendingBytes_ = 0;
  std::vector<std::uint8_t> entry_;  // the one being restored
  std::size_t entryState_ = 0;       // where its state begins (after its snapshot)
  // Per world of the phase being read: the World as the scene built it, copied at its first
  // change of bodies (what every snapshot of the phase is read against), and the last snapshot.
  std::vector<std::shared_ptr<const World>> bases_;
  std::vector<std::shared_ptr<const std::vector<std::uint8_t>>> bodySets_;
  bool ended_ = false;
  std::uint64_t endCount_ = 0;
  std::uint64_t entries_ = 0;
  void* decompressor_ = nullptr;
};

}  // namespace rbsim::app
