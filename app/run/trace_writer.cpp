#include "run/trace_writer.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "rbsim/io/input_error.h"

namespace rbsim::app {

namespace {

// %.17g: max_digits10 of a double, so every value reads back exactly.
void appendNumber(std::string& row, double value) {
  char buffer[32];
  const int n = std::snprintf(buffer, sizeof buffer, "%.17g", value);
  row.append(buffer, static_cast<std::size_t>(n));
}

}  // namespace

std::string csvField(const std::string& field) {
  if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
  std::string quoted = "\"";
  for (char c : field) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

TraceWriter::TraceWriter(const std::string& path) : path_(path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (ec) throw InputError(path, "--trace", "cannot create the trace file's folder (" + ec.message() + ")");
  if (!out_.open(path)) throw InputError(path, "--trace", "cannot create the trace file (" + out_.error() + ")");
  put("step,t,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,Lx,Ly,Lz,ke\n");
}

void TraceWriter::fail() const {
  throw InputError(path_, "--trace", "cannot write the trace file (" + out_.error() + ")");
}

void TraceWriter::put(const std::string& text) {
  if (!out_.write(text)) fail();
}

void TraceWriter::write(const World& world, std::uint64_t globalStep, double time, const std::string& bodyPrefix) {
  for (const RigidBody& body : world.bodies()) {
    const Vec3& x = body.position();
    const Quat& q = body.orientation();
    const Vec3& v = body.velocity();
    const Vec3& w = body.angularVelocity();
    const Vec3& L = body.state().angularMomentum;
    row_ = std::to_string(globalStep);
    row_ += ',';
    appendNumber(row_, time);
    row_ += ',';
    row_ += csvField(bodyPrefix + body.name());
    for (const double value : {x.x(), x.y(), x.z(), q.w(), q.x(), q.y(), q.z(), v.x(), v.y(), v.z(), w.x(), w.y(),
                               w.z(), L.x(), L.y(), L.z(), body.kineticEnergy()}) {
      row_ += ',';
      appendNumber(row_, value);
    }
    row_ += '\n';
    put(row_);
  }
}

void TraceWriter::close() {
  if (!out_.close()) fail();
}

}  // namespace rbsim::app
