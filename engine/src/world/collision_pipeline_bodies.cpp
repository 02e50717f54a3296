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
  table_->meshGround[index] = isMeshGround(body, solid) ? 1 : 0;
  table_->hasGrid[index] = solid.sdf || body.isCompound() || table_->meshGround[index] ? 1 : 0;
  table_->gap[index] = solid.implicit ? std::sqrt(3.0) * solid.sdf->cellSize() : 0.0;
  // The collision shape's, not the display mesh's (a round shape's is inscribed in it, and a body
  // built in C++ may carry any mesh): continuous collision sweeps the shape with this radius.
  double radius = body.shape().boundingRadius();
  const auto [lo, hi] = body.shape().worldBounds(Mat3::Identity(), Vec3::Zero());
  Aabb local{lo, hi};
  if (body.isCompound()) {  // its children, not their display meshes
    radius = compoundRadius(body);
    local = compoundBounds(body);
  }
  table_->radius[index] = radius;
  table_->thickness[index] = local.extents().minCoeff();
  table_->boxes[index] = bodyBounds(body).inflated(settings_.contactMargin + table_->gap[index]);
}

void CollisionPipeline::addBody(std::size_t index) {
  const RigidBody& body = table_->bodies[index];
  measure(index, body, table_->solids[index]);
  table_->proxies[index] = broad_->add(table_->boxes[index]);
  if (bodyOfProxy_.size() <= table_->proxies[index]) bodyOfProxy_.resize(table_->proxies[index] + 1);
  bodyOfProxy_[table_->proxies[index]] = index;
  table_->start[index] = body.state();
}

void CollisionPipeline::replaceBody(std::size_t index) {
  const RigidBody& body = table_->bodies[index];
  measure(index, body, table_->solids[index]);
  recycle_.clear();  // the piece is another shape: its pairs are collided afresh
  // Removed and added again, since the piece may be dynamic where the body was static; the pool
  // hands back the smallest free id, which is this one.
  broad_->remove(table_->proxies[index]);
  table_->proxies[index] = broad_->add(table_->boxes[index]);
  if (bodyOfProxy_.size() <= table_->proxies[index]) bodyOfProxy_.resize(table_->proxies[index] + 1);
  bodyOfProxy_[table_->proxies[index]] = index;
  table_->start[index] = body.state();
  table_->fast[index] = 0;
}

void CollisionPipeline::removeBodies(const BodyRemoval& removal, std::vector<std::size_t>& touched,
                                     std::vector<Contact>& reached) {
  for (const std::uint32_t gone : removal.removed()) broad_->remove(table_->proxies[gone]);
  recycle_.clear();  // keyed by body index, which the moves change: collided afresh next step
  for (const auto& [to, from] : removal.moves()) bodyOfProxy_[table_->proxies[from]] = to;
  // The swept bodies' list follows them; it stays in index order. The rows themselves move when
  // the World gathers its table (BodyTable::gather), after this.
  std::size_t keptFast = 0;
  for (const std::size_t i : fastList_) {
    const std::uint32_t to = removal.newIndex(i);
    if (to != BodyRemoval::kGone) fastList_[keptFast++] = to;
  }
  fastList_.resize(keptFast);
  std::sort(fastList_.begin(), fastList_.end());
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
