// The collision pipeline's per-body bookkeeping (world/collision_pipeline.h): each body's bounds,
// reach and broad-phase proxy as it is added, replaced by its fracture pieces or removed, with
// the contacts that follow a removal's renumbering.
#include <algorithm>
#include <cmath>

#include "world/collision_pipeline.h"
#include "world/compound_contacts.h"
#include "world/mesh_ground_contacts.h"
#include "body/body_removal.h"
#include "world/contact_renumbering.h"

namespace rbsim {

Aabb bodyBounds(const RigidBody& body) {
  if (body.isCompound()) return compoundBounds(body);
  if (!body.shape().isRound()) return Aabb::of(body.worldVertices());
  const auto [lo, hi] = body.shape().worldBounds(body.rotation(), body.position());
  return {lo, hi};
}

void CollisionPipeline::measure(std::size_t index, const RigidBody& body, const BodySolid& solid) {
  meshGround_[index] = isMeshGround(body, solid) ? 1 : 0;
  hasGrid_[index] = solid.sdf || body.isCompound() || meshGround_[index] ? 1 : 0;
  gap_[index] = solid.implicit ? std::sqrt(3.0) * solid.sdf->cellSize() : 0.0;
  // The collision shape's, not the display mesh's (a round shape's is inscribed in it, and a body
  // built in C++ may carry any mesh): continuous collision sweeps the shape with this radius.
  double radius = body.shape().boundingRadius();
  const auto [lo, hi] = body.shape().worldBounds(Mat3::Identity(), Vec3::Zero());
  Aabb local{lo, hi};
  if (body.isCompound()) {  // its children, not their display meshes
    radius = compoundRadius(body);
    local = compoundBounds(body);
  }
  radius_[index] = radius;
  thickness_[index] = local.extents().minCoeff();
  boxes_[index] = bodyBounds(body).inflated(settings_.contactMargin + gap_[index]);
}

void CollisionPipeline::addBody(const RigidBody& body, const BodySolid& solid) {
  const std::size_t index = proxies_.size();
  hasGrid_.push_back(0);
  meshGround_.push_back(0);
  gap_.push_back(0.0);
  radius_.push_back(0.0);
  thickness_.push_back(0.0);
  reach_.push_back(0.0);
  boxes_.emplace_back();
  measure(index, body, solid);
  proxies_.push_back(broad_->add(boxes_[index]));
  if (bodyOfProxy_.size() <= proxies_.back()) bodyOfProxy_.resize(proxies_.back() + 1);
  bodyOfProxy_[proxies_.back()] = index;
  start_.push_back(body.state());
  fast_.push_back(0);
}

void CollisionPipeline::replaceBody(std::size_t index, const RigidBody& body, const BodySolid& solid) {
  measure(index, body, solid);
  recycle_.clear();  // the piece is another shape: its pairs are collided afresh
  // Removed and added again, since the piece may be dynamic where the body was static; the pool
  // hands back the smallest free id, which is this one.
  broad_->remove(proxies_[index]);
  proxies_[index] = broad_->add(boxes_[index]);
  if (bodyOfProxy_.size() <= proxies_[index]) bodyOfProxy_.resize(proxies_[index] + 1);
  bodyOfProxy_[proxies_[index]] = index;
  start_[index] = body.state();
  fast_[index] = 0;
}

void CollisionPipeline::removeBodies(const BodyRemoval& removal, std::vector<std::size_t>& touched,
                                     std::vector<Contact>& reached) {
  for (const std::uint32_t gone : removal.removed()) broad_->remove(proxies_[gone]);
  recycle_.clear();  // keyed by body index, which the moves change: collided afresh next step
  for (const auto& [to, from] : removal.moves()) bodyOfProxy_[proxies_[from]] = to;
  // The swept bodies' list follows them (read before fast_ moves); it stays in index order.
  std::size_t keptFast = 0;
  for (const std::size_t i : fastList_) {
    const std::uint32_t to = removal.newIndex(i);
    if (to != BodyRemoval::kGone) fastList_[keptFast++] = to;
  }
  fastList_.resize(keptFast);
  std::sort(fastList_.begin(), fastList_.end());
  removal.gather(proxies_);
  removal.gather(radius_);
  removal.gather(thickness_);
  removal.gather(reach_);
  removal.gather(start_);
  removal.gather(fast_);
  removal.gather(hasGrid_);
  removal.gather(meshGround_);
  removal.gather(gap_);
  removal.gather(boxes_);
  // The contacts follow the bodies to their new indices (contact_renumbering.h): a removed body's
  // go, waking its partner, and the others take their bodies' new indices in the same order (a
  // pair is ordered by its bodies' keys, which stay), so that sleeping pairs keep theirs.
  sleeping_.bodiesRemoved(removal, touched, reached);
  reportedStale_ = true;
  std::size_t kept = 0;
  for (Contact& c : contacts_) {
    if (!renumberContact(c, removal, touched)) continue;
    if (&contacts_[kept] != &c) contacts_[kept] = c;  // those before the first change stay put
    ++kept;
  }
  contacts_.resize(kept);
  impacts_.clear();
}

}  // namespace rbsim
