#include "run/trace_writer.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <limits>

#include "io/input_error.h"

namespace rbsim::app {

TraceWriter::TraceWriter(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  out_.open(path);
  if (!out_) {
    const std::string why = ec ? ec.message() : std::string(std::strerror(errno));
    throw InputError(path, "--trace", "cannot create the trace file (" + why + ")");
  }
  out_ << "step,t,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,Lx,Ly,Lz,ke\n";
  out_ << std::setprecision(std::numeric_limits<double>::max_digits10);
}

void TraceWriter::write(const World& world, std::uint64_t globalStep, double time, const std::string& bodyPrefix) {
  for (const RigidBody& body : world.bodies()) {
    const Vec3& x = body.position();
    const Quat& q = body.orientation();
    const Vec3& v = body.velocity();
    const Vec3& w = body.angularVelocity();
    const Vec3& L = body.state().angularMomentum;
    out_ << globalStep << ',' << time << ',' << bodyPrefix << body.name() << ',' << x.x() << ',' << x.y() << ','
         << x.z() << ',' << q.w() << ',' << q.x() << ',' << q.y() << ',' << q.z() << ',' << v.x()
         << ',' << v.y() << ',' << v.z() << ',' << w.x() << ',' << w.y() << ',' << w.z() << ','
         << L.x() << ',' << L.y() << ',' << L.z() << ',' << body.kineticEnergy() << '\n';
  }
}

}  // namespace rbsim::app
