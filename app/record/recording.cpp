#include "record/recording.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <libdeflate.h>
#include <nlohmann/json.hpp>

#include "rbsim/world/queries.h"
#include "rbsim/world/spawner.h"
#include "rbsim/world/systems.h"
#include "rbsim/world/world_snapshot.h"
#include "record/entry_codec.h"
#include "rbsim/io/input_error.h"

namespace rbsim::app {

namespace {

// A fuzzing build (tests/fuzz/run_fuzz.sh defines this, as OSS-Fuzz does) skips the checksums:
// random bytes never match a CRC, and the fuzzer would never get past the header to the entries.
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
constexpr bool kCheckChecksums = false;
#else
constexpr bool kCheckChecksums = true;
#endif

constexpr char kMagic[8] = {'R', 'B', 'S', 'I', 'M', 'R', 'E', 'C'};
// Entries are gathered into blocks of about this many raw bytes before deflating: large enough
// for the deflater to find the repeats, small enough that a recording's memory stays flat.
constexpr std::size_t kBlockBytes = std::size_t{1} << 20;  // [bytes]
// libdeflate's fastest level: a recording is written while the run goes on.
constexpr int kDeflateLevel = 1;
// A header beyond this is not a recording's (a scene file is at most 64 MiB; a few of them).
constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t{1} << 30;  // [bytes]
// No block of ours is larger (kBlockBytes plus one entry); a damaged size asks for no more.
constexpr std::uint32_t kMaxBlockBytes = std::uint32_t{1} << 30;  // [bytes]
// Deflate's largest expansion: a 258-byte match costs at least 2 bits, so 1032 bytes out per byte
// in (RFC 1951; zlib's tech notes), plus a stream's own few bytes.
constexpr std::uint64_t kMaxDeflateRatio = 1032;       // [1]
constexpr std::uint64_t kDeflateSlackBytes = 64;       // [bytes]

}  // namespace

RecordedFile recordedFileOf(const std::string& path) {
  // A regular file only, as the loaders read (engine/src/io/read_file.cpp): a FIFO put in a mesh's
  // place would block the read for ever, a device never end (issue 56, item 7).
  std::error_code ec;
  const std::filesystem::file_type type = std::filesystem::status(path, ec).type();
  if (!ec && type != std::filesystem::file_type::regular && type != std::filesystem::file_type::not_found) {
    throw InputError(path, "--record", "is not a regular file (a folder, FIFO, device or socket); expected the file a scene read");
  }
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) throw InputError(path, "--record", std::string("cannot read it to checksum it (") + std::strerror(errno) + ")");
  RecordedFile out{std::filesystem::absolute(path).lexically_normal().string(), 0, 0};
  std::vector<std::uint8_t> buffer(std::size_t{1} << 16);
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), f)) > 0;) {
    out.crc32 = libdeflate_crc32(out.crc32, buffer.data(), n);
    out.bytes += n;
  }
  std::fclose(f);
  return out;
}

RecordWriter::RecordWriter(const std::string& path, const RecordingHeader& header) : path_(path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  // Written beside its name and renamed when closed whole (issue 56, item 7): a run that fails
  // keeps the recording of the run before. A device or FIFO is written in place.
  const std::filesystem::file_type type = std::filesystem::status(path, ec).type();
  partial_ = type == std::filesystem::file_type::regular || type == std::filesystem::file_type::not_found ? path + ".partial" : path;
  file_ = std::fopen(partial_.c_str(), "wb");
  if (file_ == nullptr) throw InputError(path, "--record", std::string("cannot create the recording (") + std::strerror(errno) + ")");
  nlohmann::json phases = nlohmann::json::array();
  for (const RecordedPhase& p : header.phases) {
    nlohmann::json files = nlohmann::json::array();
    for (const RecordedFile& f : p.files) files.push_back({{"path", f.path}, {"bytes", f.bytes}, {"crc32", f.crc32}});
    phases.push_back({{"file", p.file}, {"base_dir", p.baseDir}, {"text", p.text}, {"files", files}});
  }
  const std::string text =
      nlohmann::json{{"rbsim", header.rbsimVersion}, {"title", header.title}, {"overrides", header.overrides},
                     {"phases", phases}}.dump();
  put(kMagic, sizeof kMagic);
  put(&kRecordingVersion, sizeof kRecordingVersion);
  const std::uint64_t size = text.size();
  put(&size, sizeof size);
  put(text.data(), text.size());
  const std::uint32_t crc = libdeflate_crc32(0, text.data(), text.size());
  put(&crc, sizeof crc);
  compressor_ = libdeflate_alloc_compressor(kDeflateLevel);
  raw_.reserve(kBlockBytes + 4096);
}

RecordWriter::~RecordWriter() {
  if (file_ != nullptr) {  // not closed: the run failed, and its recording is not whole
    std::fclose(file_);
    std::error_code ec;
    if (partial_ != path_) std::filesystem::remove(partial_, ec);
  }
  if (compressor_ != nullptr) libdeflate_free_compressor(static_cast<libdeflate_compressor*>(compressor_));
}

void RecordWriter::put(const void* data, std::size_t bytes) {
  if (std::fwrite(data, 1, bytes, file_) != bytes) {
    throw InputError(path_, "--record", std::string("cannot write the recording (") + std::strerror(errno) + ")");
  }
  fileBytes_ += bytes;
}

void RecordWriter::write(std::size_t world, const World& state) {
  // The set of bodies changed in this step: the spawn stage's lists are the step's, the fracture
  // events accumulate over the run (a world's first step starts its count again: a new phase).
  if (world >= fractures_.size()) fractures_.resize(world + 1, 0);
  if (state.stepCount() == 1) fractures_[world] = 0;
  const bool changed = !spawnedBodies(state).empty() || !removedBodies(state).empty() ||
                       fractureEvents(state).size() != fractures_[world];
  fractures_[world] = fractureEvents(state).size();
  std::vector<std::uint8_t> bodySet;
  if (changed) {
    try {
      bodySet = saveWorldSnapshot(state);
    } catch (const std::invalid_argument& e) {
      throw InputError(path_, "--record", std::string("the bodies changed at step ") + std::to_string(state.stepCount()) +
                                              ", and a recording keeps them as a World snapshot: " + e.what());
    }
    ++snapshots_;
  }
  appendEntry(raw_, world, state, changed ? &bodySet : nullptr);
  ++entries_;
  const PlanarWorld* planar = planarWorld(state);
  bodySteps_ += state.bodies().size() + (planar ? planar->bodies().size() : 0);
  if (raw_.size() >= kBlockBytes) flush();
}

void RecordWriter::flush() {
  if (raw_.empty()) return;
  auto* compressor = static_cast<libdeflate_compressor*>(compressor_);
  deflated_.resize(libdeflate_deflate_compress_bound(compressor, raw_.size()));
  const std::size_t deflated = libdeflate_deflate_compress(compressor, raw_.data(), raw_.size(), deflated_.data(), deflated_.size());
  const std::uint32_t sizes[3] = {static_cast<std::uint32_t>(raw_.size()), static_cast<std::uint32_t>(deflated),
                                  libdeflate_crc32(0, deflated_.data(), deflated)};
  put(sizes, sizeof sizes);
  put(deflated_.data(), deflated);
  raw_.clear();
}

void RecordWriter::close() {
  if (file_ == nullptr) return;
  flush();
  // The end: an empty block whose CRC field counts the entries (low 32 bits; the count follows).
  const std::uint32_t end[3] = {0, 0, static_cast<std::uint32_t>(entries_)};
  put(end, sizeof end);
  put(&entries_, sizeof entries_);
  const bool failed = std::fclose(file_) != 0;
  const int error = errno;
  file_ = nullptr;
  std::error_code ec;
  if (failed) {
    if (partial_ != path_) std::filesystem::remove(partial_, ec);
    throw InputError(path_, "--record", std::string("cannot write the recording (") + std::strerror(error) + ")");
  }
  if (partial_ != path_) {
    std::filesystem::rename(partial_, path_, ec);
    if (ec) {
      std::filesystem::remove(partial_, ec);
      throw InputError(path_, "--record", "cannot move the finished recording into place (" + ec.message() + ")");
    }
  }
}

RecordReader::RecordReader(const std::string& path) : path_(path) {
  if (std::filesystem::is_directory(path)) fail("is a folder, not a recording");
  file_.reset(std::fopen(path.c_str(), "rb"));
  if (file_ == nullptr) fail(std::string("cannot open it (") + std::strerror(errno) + ")");
  char magic[sizeof kMagic] = {};
  if (std::fread(magic, 1, sizeof magic, file_.get()) != sizeof magic || std::memcmp(magic, kMagic, sizeof kMagic) != 0) {
    fail("not an rbsim recording (it does not start with RBSIMREC)");
  }
  std::uint32_t version = 0;
  std::uint64_t size = 0;
  if (std::fread(&version, sizeof version, 1, file_.get()) != 1) fail("truncated in its header");
  if (version != kRecordingVersion) {
    fail("a recording of format version " + std::to_string(version) + "; this rbsim reads version " +
         std::to_string(kRecordingVersion) + " only");
  }
  if (std::fread(&size, sizeof size, 1, file_.get()) != 1) fail("truncated in its header");
  if (size > kMaxHeaderBytes) fail("its header claims " + std::to_string(size) + " bytes; a recording's is at most 1 GiB");
  // Before allocating: a damaged length must not ask for more memory than the file holds (the
  // recording fuzzer's 369-byte file claimed 512 MiB).
  std::error_code sizeError;
  fileBytes_ = std::filesystem::file_size(path, sizeError);
  if (sizeError) fail("cannot tell its size (" + sizeError.message() + ")");
  if (size > remainingBytes()) {
    fail("its header claims " + std::to_string(size) + " bytes, but only " + std::to_string(remainingBytes()) +
         " follow: truncated or damaged");
  }
  std::string text(size, '\0');
  if (std::fread(text.data(), 1, size, file_.get()) != size) fail("truncated in its header");
  std::uint32_t crc = 0;
  if (std::fread(&crc, sizeof crc, 1, file_.get()) != 1) fail("truncated in its header");
  if (kCheckChecksums && crc != libdeflate_crc32(0, text.data(), text.size())) {
    fail("its header (the scenes and settings it ran) does not match its checksum: it was edited or damaged");
  }
  try {
    const nlohmann::json h = nlohmann::json::parse(text);
    header_.rbsimVersion = h.at("rbsim").get<std::string>();
    header_.title = h.at("title").get<std::string>();
    header_.overrides = h.at("overrides").get<std::vector<std::string>>();
    for (const nlohmann::json& p : h.at("phases")) {
      RecordedPhase phase{p.at("file").get<std::string>(), p.at("base_dir").get<std::string>(), p.at("text").get<std::string>(), {}};
      for (const nlohmann::json& f : p.at("files")) {
        phase.files.push_back({f.at("path").get<std::string>(), f.at("bytes").get<std::uint64_t>(), f.at("crc32").get<std::uint32_t>()});
      }
      header_.phases.push_back(std::move(phase));
    }
  } catch (const nlohmann::json::exception& e) {
    fail(std::string("its header is damaged (") + e.what() + ")");
  }
  if (header_.rbsimVersion != RBSIM_VERSION) {
    fail("recorded by rbsim " + header_.rbsimVersion + "; this is rbsim " + RBSIM_VERSION +
         ", whose scenes may read differently: replay it with the rbsim that recorded it");
  }
  if (header_.phases.empty()) fail("its header lists no scene");
  decompressor_ = libdeflate_alloc_decompressor();
}

RecordReader::~RecordReader() {
  if (decompressor_ != nullptr) libdeflate_free_decompressor(static_cast<libdeflate_decompressor*>(decompressor_));
}

void RecordReader::fail(const std::string& problem) const { throw InputError(path_, "", problem); }

std::uint64_t RecordReader::remainingBytes() const {
  const long position = std::ftell(file_.get());
  if (position < 0 || static_cast<std::uintmax_t>(position) > fileBytes_) return 0;
  return fileBytes_ - static_cast<std::uintmax_t>(position);
}

bool RecordReader::loadBlock() {
  std::uint32_t sizes[3];
  if (std::fread(sizes, sizeof sizes, 1, file_.get()) != 1) {
    fail("truncated after " + std::to_string(entries_) + " steps: the recording was not finished");
  }
  if (sizes[0] == 0) {
    if (std::fread(&endCount_, sizeof endCount_, 1, file_.get()) != 1) fail("truncated at its end marker");
    // Every byte of the end is checked: its two copies of the count agree, and nothing follows.
    if (sizes[1] != 0 || sizes[2] != static_cast<std::uint32_t>(endCount_)) fail("its end marker is damaged");
    if (std::fgetc(file_.get()) != EOF) fail("has data after its end marker: it is damaged or two files were joined");
    ended_ = true;
    return false;
  }
  if (sizes[0] > kMaxBlockBytes || sizes[1] > kMaxBlockBytes) fail("a block claims more than 1 GiB: the file is damaged");
  // Before allocating (the fuzzer again): the stored bytes must be in the file, and deflate
  // cannot inflate them more than kMaxDeflateRatio-fold.
  if (sizes[1] > remainingBytes() || sizes[0] > kMaxDeflateRatio * std::uint64_t{sizes[1]} + kDeflateSlackBytes) {
    fail("a block after step " + std::to_string(entries_) + " claims " + std::to_string(sizes[1]) + " stored bytes (" +
         std::to_string(remainingBytes()) + " follow) inflating to " + std::to_string(sizes[0]) +
         ": truncated or damaged");
  }
  std::vector<std::uint8_t> deflated(sizes[1]);
  if (std::fread(deflated.data(), 1, deflated.size(), file_.get()) != deflated.size()) {
    fail("truncated after " + std::to_string(entries_) + " steps: the recording was not finished");
  }
  // The checksum is of the stored bytes, so it sees every bit of them: a flip in the padding bits
  // after a deflate stream's last code changes nothing the inflater reads (the raw bytes' checksum
  // let one through).
  if (kCheckChecksums && libdeflate_crc32(0, deflated.data(), deflated.size()) != sizes[2]) {
    fail("a block after step " + std::to_string(entries_) + " is damaged (its bytes do not match their checksum)");
  }
  block_.resize(sizes[0]);
  std::size_t out = 0;
  const libdeflate_result result = libdeflate_deflate_decompress(
      static_cast<libdeflate_decompressor*>(decompressor_), deflated.data(), deflated.size(), block_.data(), block_.size(), &out);
  if (result != LIBDEFLATE_SUCCESS || out != block_.size()) {
    fail("a block after step " + std::to_string(entries_) + " is damaged (its data do not inflate to its size)");
  }
  offset_ = 0;
  return true;
}

void RecordReader::checkFiles(std::size_t phase) const {
  for (const RecordedFile& recorded : header_.phases.at(phase).files) {
    RecordedFile now;
    try {
      now = recordedFileOf(recorded.path);
    } catch (const InputError& e) {
      fail("its scene read " + recorded.path + ", which is gone, unreadable or not a regular file now (" + e.problem() + ")");
    }
    if (now.bytes != recorded.bytes || now.crc32 != recorded.crc32) {
      fail("its scene read " + recorded.path + ", which has changed since it was recorded (" + std::to_string(recorded.bytes) +
           " bytes then, " + std::to_string(now.bytes) + " now; CRC-32 differs): the poses would be drawn on another mesh");
    }
  }
}

void RecordReader::restoreNext(std::size_t index, std::size_t worldCount, World& world) {
  if (index >= bases_.size()) {
    bases_.resize(index + 1);
    bodySets_.resize(index + 1);
  }
  if (world.stepCount() == 0) {  // a phase's World as its scene built it: a new phase
    bases_[index].reset();
    bodySets_[index].reset();
  }
  // Entries come in the order the recording run stepped its worlds. A replay at another frame
  // rate steps a compared phase's worlds in another order, so entries of the others wait.
  if (index >= pending_.size()) pending_.resize(index + 1);
  while (pending_[index].empty()) {
    if (offset_ >= block_.size() && (ended_ || !loadBlock())) {
      fail("ends after " + std::to_string(entries_) + " steps, before the scene does");
    }
    std::uint16_t owner = 0;
    const std::size_t length = entryLength(block_.data() + offset_, block_.size() - offset_, [this](const std::string& p) { fail(p); });
    std::memcpy(&owner, block_.data() + offset_, sizeof owner);
    owner = static_cast<std::uint16_t>(owner & ~kBodySetFlag);
    if (owner >= worldCount) {
      fail("an entry names world " + std::to_string(owner) + ", and the scene has " + std::to_string(worldCount) +
           (worldCount == 1 ? " world" : " worlds") + ": the recording does not belong to it, or is damaged");
    }
    if (owner >= pending_.size()) pending_.resize(owner + 1);
    pendingBytes_ += length;
    if (pendingBytes_ > kMaxPendingBytes) {
      fail("entries of other worlds run more than " + std::to_string(kMaxPendingBytes >> 20) + " MiB ahead of world " +
           std::to_string(index) + "'s: the recording is damaged");
    }
    pending_[owner].emplace_back(block_.begin() + static_cast<std::ptrdiff_t>(offset_),
                                 block_.begin() + static_cast<std::ptrdiff_t>(offset_ + length));
    offset_ += length;
  }
  entry_ = std::move(pending_[index].front());
  pending_[index].pop_front();
  pendingBytes_ -= entry_.size();
  restoreEntry(index, world, /*nextStep=*/true);
  ++entries_;
}

KeptEntry RecordReader::lastEntry() const {
  KeptEntry kept;
  if (entry_.empty()) return kept;
  std::uint16_t world = 0;
  std::memcpy(&world, entry_.data(), sizeof world);
  world = static_cast<std::uint16_t>(world & ~kBodySetFlag);
  kept.state.resize(sizeof world + (entry_.size() - entryState_));
  std::memcpy(kept.state.data(), &world, sizeof world);
  std::copy(entry_.begin() + static_cast<std::ptrdiff_t>(entryState_), entry_.end(), kept.state.begin() + sizeof world);
  if (world < bodySets_.size() && bodySets_[world]) {
    kept.bodySet = bodySets_[world];
    kept.base = bases_[world];
  }
  return kept;
}

void RecordReader::restore(const KeptEntry& entry, std::size_t index, World& world) {
  if (entry.bodySet) {
    try {
      world = loadWorldSnapshot(*entry.bodySet, *entry.base, path_);
    } catch (const std::invalid_argument& e) {
      fail(std::string("a kept step's bodies cannot be made again (") + e.what() + ")");
    }
  }
  entry_ = entry.state;
  restoreEntry(index, world, /*nextStep=*/false);
}

void RecordReader::restoreEntry(std::size_t index, World& world, bool nextStep) {
  const EntryFail failHere = [this](const std::string& problem) { fail(problem); };
  const EntryParts parts = entryParts(entry_, failHere);
  if (parts.world != index) {
    fail("entry " + std::to_string(entries_) + " is of world " + std::to_string(parts.world) + "; the scene expects world " +
         std::to_string(index) + ": the recording does not belong to these scenes");
  }
  entryState_ = parts.stateOffset;
  if (parts.snapshot != nullptr) {
    // The bodies changed in this step: the World the snapshot gives, read against the World of
    // the step before, whose bodies, spawners and fracture patterns have every shape the step
    // can have made, and whose mesh objects the bodies that stay keep (the renderer uploads a
    // mesh once, when it first sees it). The scene's World, copied at the phase's first change,
    // is what a kept entry's snapshot is read against (lastEntry).
    if (!bases_[index]) bases_[index] = std::make_shared<const World>(world);
    World changed = [&] {
      try {
        return loadWorldSnapshot(parts.snapshot, parts.snapshotBytes, world,
                                 "entry " + std::to_string(entries_) + "'s bodies");
      } catch (const std::invalid_argument& e) {
        fail(std::string(e.what()) + ": the recording is damaged or does not belong to these scenes");
      }
    }();
    if (nextStep && changed.stepCount() != world.stepCount() + 1) {
      fail("entry " + std::to_string(entries_) + "'s bodies are of step " + std::to_string(changed.stepCount()) +
           "; the scene expects step " + std::to_string(world.stepCount() + 1) + ": the recording is damaged");
    }
    const std::uint64_t step = changed.stepCount();
    world = std::move(changed);
    bodySets_[index] = std::make_shared<const std::vector<std::uint8_t>>(parts.snapshot, parts.snapshot + parts.snapshotBytes);
    restoreState(entry_, parts, entries_, /*nextStep=*/false, world, failHere);
    if (world.stepCount() != step) {
      fail("entry " + std::to_string(entries_) + " is step " + std::to_string(world.stepCount()) + ", its bodies step " +
           std::to_string(step) + ": the recording is damaged");
    }
    return;
  }
  restoreState(entry_, parts, entries_, nextStep, world, failHere);
}

void RecordReader::expectEnd() {
  for (const auto& waiting : pending_) {
    if (!waiting.empty()) fail("holds more steps than its scenes run: it does not belong to them");
  }
  if (offset_ < block_.size()) fail("holds more steps than its scenes run: it does not belong to them");
  if (!ended_ && loadBlock()) fail("holds more steps than its scenes run: it does not belong to them");
  if (endCount_ != entries_) fail("its end counts " + std::to_string(endCount_) + " steps, " + std::to_string(entries_) + " were read");
}

}  // namespace rbsim::app
