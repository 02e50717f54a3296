// Stage BreakBodies of World::step (seed 000 "Fracture"): a breakable body whose contacts took
// more normal impulse this step than its pattern's threshold becomes its pieces. The first piece
// takes the body's index, so every index held elsewhere stays valid; the others are appended.
#include <algorithm>
#include <string>

#include "rbsim/world/world.h"
#include "world/collision_pipeline.h"
#include "world/contact_event_tracker.h"

#include "rbsim/fracture/fracture.h"

namespace rbsim {

void World::breakBodies() {
  receivedImpulse_.assign(table_->bodies.size(), 0.0);
  const std::vector<Contact>& contacts = collision_->contacts();
  for (const SolvedContactPoint& point : contactPoints()) {
    const Contact& contact = contacts[point.contact];
    receivedImpulse_[contact.b] += point.normalImpulse;
    if (contact.kind == Contact::Kind::BodyBody) receivedImpulse_[contact.a] += point.normalImpulse;
  }
  const std::size_t count = table_->bodies.size();  // pieces appended below are not looked at
  for (std::size_t i = 0; i < count; ++i) {
    if (table_->fracturePatterns[i] && receivedImpulse_[i] > table_->fracturePatterns[i]->impulseThreshold) {
      breakBody(i, receivedImpulse_[i]);
    }
  }
}

void World::breakBody(std::size_t body, double impulse) {
  const std::shared_ptr<const FracturePattern> pattern = std::move(table_->fracturePatterns[body]);
  --breakableBodies_;
  // The pieces start from the state the solver left: the impulse that broke the body is in it.
  std::vector<BodyDef> pieces = fracturePieces(table_->bodies[body], *pattern, table_->materials[body]);
  const BodyId id = idAt(body);
  FractureEvent event{time(), id, {}, impulse};
  contactEvents_->bodyBroken(*this, *collision_, body);  // a piece that touches on begins anew
  table_->bodies[body] = RigidBody(pieces.front());
  table_->solids[body] = bodySolidOf(pieces.front());
  collision_->replaceBody(body);
  // Its shapes are the first piece's now: the broken body's shape ids go stale (Box2D destroys a
  // body's shapes and makes new ones the same way), the body's own id stays.
  table_->shapeIds.retire(bodyKeys()[body]);
  table_->shapeIds.add(bodyKeys()[body], shapeCountOf(table_->bodies[body]));
  awakeStale_ = true;  // its pieces are added awake
  for (std::size_t k = 1; k < pieces.size(); ++k) event.added.push_back(addBody(pieces[k]));
  // The pieces are new bodies with their own centres of mass: the broken body's joints let go.
  jointIds_.erase(joints_, [&](const Joint& j) { return j.def.bodyA == id || j.def.bodyB == id; });  // their ids go stale
  updateJointFilter();
  fractureEvents_.push_back(event);
}

}  // namespace rbsim
