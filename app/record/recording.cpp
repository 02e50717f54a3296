#include "record/recording.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <libdeflate.h>
#include <nlohmann/json.hpp>

#include "rbsim/world/systems.h"
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

// Bytes of one body, particle and soft-body node in an entry (recording.h): x, q, P, L and the
// awake byte; x, v, 1/m, age, lifetime, colour (3 floats) and size; x and v.
constexpr std::size_t kBodyEntryBytes = 13 * sizeof(double) + 1;
constexpr std::size_t kParticleEntryBytes = 9 * sizeof(double) + 4 * sizeof(float);
constexpr std::size_t kSoftNodeEntryBytes = 6 * sizeof(double);

template <typename T>
void append(std::vector<std::uint8_t>& out, const T& value) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(&value);
  out.insert(out.end(), bytes, bytes + sizeof(T));
}

void appendVec(std::vector<std::uint8_t>& out, const Vec3& v) {
  for (int i = 0; i < 3; ++i) append(out, v[i]);
}

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
  append(raw_, static_cast<std::uint16_t>(world));
  append(raw_, state.stepCount());
  append(raw_, static_cast<std::uint32_t>(state.bodies().size()));
  for (const RigidBody& b : state.bodies()) {
    const BodyState& s = b.state();
    appendVec(raw_, s.position);
    for (const double c : {s.orientation.w(), s.orientation.x(), s.orientation.y(), s.orientation.z()}) append(raw_, c);
    appendVec(raw_, s.linearMomentum);
    appendVec(raw_, s.angularMomentum);
    append(raw_, static_cast<std::uint8_t>(b.awake() ? 1 : 0));
  }
  append(raw_, static_cast<std::uint32_t>(particleSystems(state).size()));
  for (const ParticleSystem& system : particleSystems(state)) {
    const ParticleStore& p = system.particles();
    append(raw_, static_cast<std::uint32_t>(p.count()));
    for (std::size_t i = 0; i < p.count(); ++i) {
      appendVec(raw_, p.position[i]);
      appendVec(raw_, p.velocity[i]);
      append(raw_, p.inverseMass[i]);
      append(raw_, p.age[i]);
      append(raw_, p.lifetime[i]);
      for (int c = 0; c < 3; ++c) append(raw_, p.color[i][c]);
      append(raw_, p.size[i]);
    }
  }
  append(raw_, static_cast<std::uint32_t>(softBodies(state).size()));
  for (const SoftBody& soft : softBodies(state)) {
    append(raw_, static_cast<std::uint32_t>(soft.positions().size()));
    for (const Vec3& x : soft.positions()) appendVec(raw_, x);
    for (const Vec3& v : soft.velocities()) appendVec(raw_, v);
  }
  ++entries_;
  bodySteps_ += state.bodies().size();
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

void RecordReader::take(void* out, std::size_t bytes) {
  if (bytes > entry_.size() - entryOffset_) fail("an entry runs past its end: the file is damaged");
  std::memcpy(out, entry_.data() + entryOffset_, bytes);
  entryOffset_ += bytes;
}

std::size_t RecordReader::entryLength() const {
  std::size_t at = offset_;
  const auto skip = [&](std::size_t bytes) {
    if (bytes > block_.size() - at) fail("an entry runs past its block: the file is damaged");
    at += bytes;
  };
  const auto count = [&] {
    std::uint32_t n = 0;
    skip(sizeof n);
    std::memcpy(&n, block_.data() + at - sizeof n, sizeof n);
    return static_cast<std::size_t>(n);
  };
  skip(sizeof(std::uint16_t) + sizeof(std::uint64_t));  // world, step
  skip(count() * kBodyEntryBytes);
  for (std::size_t systems = count(), i = 0; i < systems; ++i) skip(count() * kParticleEntryBytes);
  for (std::size_t softBodies = count(), i = 0; i < softBodies; ++i) skip(count() * kSoftNodeEntryBytes);
  return at - offset_;
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
  // Entries come in the order the recording run stepped its worlds. A replay at another frame
  // rate steps a compared phase's worlds in another order, so entries of the others wait.
  if (index >= pending_.size()) pending_.resize(index + 1);
  while (pending_[index].empty()) {
    if (offset_ >= block_.size() && (ended_ || !loadBlock())) {
      fail("ends after " + std::to_string(entries_) + " steps, before the scene does");
    }
    std::uint16_t owner = 0;
    const std::size_t length = entryLength();
    std::memcpy(&owner, block_.data() + offset_, sizeof owner);
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

void RecordReader::restore(const std::vector<std::uint8_t>& entry, std::size_t index, World& world) {
  entry_ = entry;
  restoreEntry(index, world, /*nextStep=*/false);
}

void RecordReader::restoreEntry(std::size_t index, World& world, bool nextStep) {
  entryOffset_ = 0;
  const auto get = [&](auto& value) { take(&value, sizeof value); };
  const auto getVec = [&](Vec3& v) {
    for (int i = 0; i < 3; ++i) get(v[i]);
  };
  std::uint16_t worldIndex = 0;
  std::uint64_t step = 0;
  std::uint32_t bodies = 0;
  get(worldIndex);
  get(step);
  get(bodies);
  if (worldIndex != index || (nextStep && step != world.stepCount() + 1) || bodies != world.bodies().size()) {
    fail("entry " + std::to_string(entries_) + " is step " + std::to_string(step) + " of world " + std::to_string(worldIndex) +
         " with " + std::to_string(bodies) + " bodies; the scene expects step " + std::to_string(world.stepCount() + 1) +
         " of world " + std::to_string(index) + " with " + std::to_string(world.bodies().size()) +
         ": the recording does not belong to these scenes");
  }
  states_.resize(bodies);
  awake_.resize(bodies);
  for (std::uint32_t i = 0; i < bodies; ++i) {
    BodyState& s = states_[i];
    getVec(s.position);
    double q[4];
    for (double& c : q) get(c);
    s.orientation = Quat(q[0], q[1], q[2], q[3]);
    getVec(s.linearMomentum);
    getVec(s.angularMomentum);
    std::uint8_t awake = 0;
    get(awake);
    awake_[i] = static_cast<char>(awake);
    // Validated as a scene's values are: a damaged or forged entry must not reach the World.
    if (!s.position.allFinite() || !s.linearMomentum.allFinite() || !s.angularMomentum.allFinite() ||
        !s.orientation.coeffs().allFinite()) {
      fail("entry " + std::to_string(entries_) + ": body " + std::to_string(i) + "'s state is not finite");
    }
    if (std::abs(s.orientation.norm() - 1.0) > kRotationTolerance) {
      fail("entry " + std::to_string(entries_) + ": body " + std::to_string(i) + "'s orientation is not a unit quaternion (|q| = " +
           std::to_string(s.orientation.norm()) + ")");
    }
    if (awake > 1) fail("entry " + std::to_string(entries_) + ": body " + std::to_string(i) + "'s awake flag is " + std::to_string(awake));
  }
  world.restore(step, states_, awake_);
  std::uint32_t systems = 0;
  get(systems);
  if (systems != particleSystems(world).size()) fail("an entry's particle systems do not match the scene's");
  for (ParticleSystem& system : particleSystems(world)) {
    ParticleStore& p = system.particles();
    std::uint32_t count = 0;
    get(count);
    if (count > p.capacity()) fail("an entry holds more particles than the scene's system can");
    p.setCount(count);
    for (std::size_t i = 0; i < count; ++i) {
      getVec(p.position[i]);
      getVec(p.velocity[i]);
      get(p.inverseMass[i]);
      get(p.age[i]);
      get(p.lifetime[i]);
      for (int c = 0; c < 3; ++c) get(p.color[i][c]);
      get(p.size[i]);
      if (!p.position[i].allFinite() || !p.velocity[i].allFinite() || !std::isfinite(p.inverseMass[i]) ||
          !std::isfinite(p.age[i]) || !std::isfinite(p.lifetime[i]) || !std::isfinite(p.size[i])) {
        fail("entry " + std::to_string(entries_) + ": particle " + std::to_string(i) + " is not finite");
      }
    }
  }
  std::uint32_t softCount = 0;
  get(softCount);
  if (softCount != softBodies(world).size()) fail("an entry's soft bodies do not match the scene's");
  for (SoftBody& soft : softBodies(world)) {
    std::uint32_t nodes = 0;
    get(nodes);
    if (nodes != soft.positions().size()) fail("an entry's soft body nodes do not match the scene's");
    for (Vec3& x : soft.positions()) getVec(x);
    for (Vec3& v : soft.velocities()) getVec(v);
    for (std::size_t n = 0; n < nodes; ++n) {
      if (!soft.positions()[n].allFinite() || !soft.velocities()[n].allFinite()) {
        fail("entry " + std::to_string(entries_) + ": soft body node " + std::to_string(n) + " is not finite");
      }
    }
  }
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
