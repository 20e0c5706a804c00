#include "job/state_rows.hpp"

namespace tumble::job {

io::StateRow state_row(const physics::BodyState& s) {
  const physics::Vec3& x = s.position();
  const physics::Vec3& v = s.velocity();
  const physics::Quat& q = s.orientation();
  const physics::Vec3& w = s.angular_velocity();
  const physics::Vec3& p = s.momentum();
  const physics::Vec3& l = s.angular_momentum();
  return {
      x.x(), x.y(), x.z(), v.x(), v.y(), v.z(), q.w(), q.x(), q.y(), q.z(),
      w.x(), w.y(), w.z(), p.x(), p.y(), p.z(), l.x(), l.y(), l.z(), physics::kinetic_energy(s)};
}

}  // namespace tumble::job
