// The collision pipeline's passes beside the pair loop (world/collision_pipeline.h): contact
// recycling's frames, and the pass over pairs with a compound body or a mesh ground, which give
// several contacts a pair.
#include <algorithm>

#include "rbsim/math/parallel.h"
#include "world/collision_pipeline.h"
#include "world/compound_contacts.h"
#include "world/mesh_ground_contacts.h"

namespace rbsim {

std::uint64_t CollisionPipeline::keptKey(Contact::Kind kind, std::size_t a, std::size_t b) {
  // Either order for two bodies: the pair is named alike whichever its contact puts first.
  if (kind == Contact::Kind::BodyBody && a > b) std::swap(a, b);
  return (std::uint64_t{kind == Contact::Kind::PlaneBody} << 63) | (std::uint64_t{a} << 32) | std::uint64_t{b};
}

std::optional<ContactManifold> CollisionPipeline::recycled(Contact::Kind kind, std::size_t a, std::size_t b,
                                                          const RecyclePose& poseA, const RecyclePose& poseB,
                                                          RecycleFrame& frame) const {
  const std::uint64_t key = keptKey(kind, a, b);
  const std::optional<std::uint32_t> slot = recycle_.find(key);
  if (!slot) return std::nullopt;
  const RecycleFrame& last =
      *slot < keptPairFrames_.size() ? keptPairFrames_[*slot] : keptPlaneFrames_[*slot - keptPairFrames_.size()];
  // poseA and poseB in the contact's order (bodiesOf), which the frame kept keeps.
  std::optional<ContactManifold> m = recycledManifold(last, poseA, poseB, recycleTolerance_, settings_.contactMargin);
  if (m) {
    frame = last;
    ++frame.age;
  }
  return m;
}

void CollisionPipeline::keepFrames() {
  const auto kept = [&](std::size_t k) {
    return later_[k] == Later::Nothing && pairSlots_[k].manifold.count > 0 && pairFrames_[k].count > 0;
  };
  const auto keptPlane = [&](std::size_t k) { return planeSlots_[k].manifold.count > 0 && planeFrames_[k].count > 0; };
  std::size_t count = 0;
  for (std::size_t k = 0; k < pairSlots_.size(); ++k) count += kept(k);
  for (std::size_t k = 0; k < planeSlots_.size(); ++k) count += keptPlane(k);
  recycle_.reset(count);
  recycledCount_ = 0;
  const std::size_t pairs = pairSlots_.size();
  for (std::size_t k = 0; k < pairs; ++k) {
    if (!kept(k)) continue;
    recycle_.insert(pairFrames_[k].key, static_cast<std::uint32_t>(k));
    recycledCount_ += pairFrames_[k].age > 0;
  }
  for (std::size_t k = 0; k < planeSlots_.size(); ++k) {
    if (!keptPlane(k)) continue;
    recycle_.insert(planeFrames_[k].key, static_cast<std::uint32_t>(pairs + k));
    recycledCount_ += planeFrames_[k].age > 0;
  }
  // This step's frames become the last step's; the arrays are refilled next step.
  keptPairFrames_.swap(pairFrames_);
  keptPlaneFrames_.swap(planeFrames_);
}

void CollisionPipeline::collideCompounds(const std::vector<ProxyPair>& pairs, int threads) {
  const std::vector<RigidBody>& bodies = table_->bodies;
  const std::vector<BodySolid>& shapes = table_->solids;
  compoundWork_.clear();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (later_[k] == Later::Compound || later_[k] == Later::MeshGround) compoundWork_.push_back(k);
  }
  if (compoundWork_.empty()) return;
  if (compoundSlots_.size() < pairs.size()) compoundSlots_.resize(pairs.size());
  parallelFor(compoundWork_.size(), threads, [&](std::size_t w) {
    const std::size_t k = compoundWork_[w];
    std::vector<Contact>& out = compoundSlots_[k];
    out.clear();
    const ProxyPair pair = bodiesOf(pairs[k]);
    const RigidBody& a = bodies[pair.a];
    const RigidBody& b = bodies[pair.b];
    if (!a.awake() && !b.awake()) return;  // kept apart with their island's (keepSleeping)
    const double margin = settings_.contactMargin + table_->reach[pair.a] + table_->reach[pair.b];
    if (later_[k] == Later::MeshGround) {
      const bool groundIsA = table_->meshGround[pair.a] != 0;
      const std::size_t ig = groundIsA ? pair.a : pair.b, io = groundIsA ? pair.b : pair.a;
      collideMeshGround(bodies[ig], ig, *shapes[ig].triangles, bodies[io], io, groundIsA, margin, out);
      return;
    }
    collideCompoundPair(a, pair.a, b, pair.b, margin, out);
  });
}

}  // namespace rbsim
