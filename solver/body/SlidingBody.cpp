#include "body/SlidingBody.h"

#include <cmath>
#include <string>
#include <tuple>

namespace wcmps {

SlidingBody::SlidingBody(const BodySpec& spec, const BodyParticles& particles, Vec2 gravity,
                         const ParticleState& initial)
    : spec_(spec), particles_(particles), gravity_(gravity), mass_(spec.density * particles.area) {
  if (spec_.motion.type == BodyMotionType::Table) {
    table_.emplace(spec_.motion.times, spec_.motion.distances);
  }
  for (const auto& [b, e] : {particles_.walls, particles_.ghosts}) {
    for (std::int64_t i = b; i < e; ++i) {
      x0_.push_back(initial.x[i]);
      y0_.push_back(initial.y[i]);
    }
  }
}

double SlidingBody::free_acceleration(double u, const BodyForce& f) const {
  const Vec2 load = gravity_ * mass_ + f.total();
  const double along = dot(load, spec_.downslope);
  const double friction = spec_.motion.friction * std::max(0.0, -dot(load, spec_.bed_normal));
  if (u > 0.0) return (along - friction) / mass_;
  if (u < 0.0) return (along + friction) / mass_;
  if (std::abs(along) <= friction) return 0.0;  // static friction holds it
  return (along - std::copysign(friction, along)) / mass_;
}

SlideState SlidingBody::advance(double time, double dt) const {
  if (held_) return {state_.s, 0.0, 0.0};
  switch (spec_.motion.type) {
    case BodyMotionType::Fixed:
      return state_;
    case BodyMotionType::Table:
      return table_->at(time + dt);
    case BodyMotionType::LnCosh:
      return LnCoshSlide{spec_.motion.a0, spec_.motion.ut}.at(time + dt);
    case BodyMotionType::Free:
      break;
  }
  const double u = state_.u;
  double u_next = u + dt * free_acceleration(u, force_);
  // Friction stops the slide within the step; it cannot send it back.
  if ((u > 0.0 && u_next < 0.0) || (u < 0.0 && u_next > 0.0)) u_next = 0.0;
  return {state_.s + dt * u_next, u_next, (u_next - u) / dt};
}

void SlidingBody::place(const SlideState& s, ParticleState& st) const {
  const Vec2 d = offset(s.s), v = spec_.downslope * s.u;
  std::size_t k = 0;
  for (const auto& [b, e] : {particles_.walls, particles_.ghosts}) {
    for (std::int64_t i = b; i < e; ++i, ++k) {
      st.x[i] = x0_[k] + d.x;
      st.y[i] = y0_[k] + d.y;
      st.u[i] = v.x;
      st.v[i] = v.y;
    }
  }
}

void SlidingBody::commit(const SlideState& s, const BodyForce& f) {
  state_ = s;
  force_ = f;
}

std::vector<Vec2> SlidingBody::outline(double s) const {
  std::vector<Vec2> out = particles_.outline;
  for (Vec2& p : out) p += offset(s);
  return out;
}

std::pair<double, double> SlidingBody::support(const SlideState& s, const BodyForce& f) const {
  const Vec2 load = gravity_ * mass_ + f.total();
  return {std::max(0.0, -dot(load, spec_.bed_normal)), mass_ * s.a - dot(load, spec_.downslope)};
}

BodySample SlidingBody::sample(double time) const {
  BodySample b;
  b.time = time;
  b.state = state_;
  b.force = force_;
  std::tie(b.normal, b.along) = support(state_, force_);
  return b;
}

void SlidingBody::save(StateWriter& out) const {
  out.scalar("body_s", state_.s);
  out.scalar("body_u", state_.u);
  out.scalar("body_a", state_.a);
  out.scalar("body_pressure_force_x", force_.pressure.x);
  out.scalar("body_pressure_force_y", force_.pressure.y);
  out.scalar("body_viscous_force_x", force_.viscous.x);
  out.scalar("body_viscous_force_y", force_.viscous.y);
  out.integer("body_held", held_ ? 1 : 0);
}

void SlidingBody::load(StateReader& in) {
  state_ = {in.scalar("body_s"), in.scalar("body_u"), in.scalar("body_a")};
  force_.pressure = {in.scalar("body_pressure_force_x"), in.scalar("body_pressure_force_y")};
  force_.viscous = {in.scalar("body_viscous_force_x"), in.scalar("body_viscous_force_y")};
  held_ = in.integer("body_held") != 0;
}

namespace {
/// The columns of a history, in the order of block.csv.
template <class F>
void for_each_history_column(F&& f) {
  f(
      "time", [](auto& b) -> auto& { return b.time; });
  f(
      "S", [](auto& b) -> auto& { return b.state.s; });
  f(
      "U", [](auto& b) -> auto& { return b.state.u; });
  f(
      "A", [](auto& b) -> auto& { return b.state.a; });
  f(
      "pressure_force_x", [](auto& b) -> auto& { return b.force.pressure.x; });
  f(
      "pressure_force_y", [](auto& b) -> auto& { return b.force.pressure.y; });
  f(
      "viscous_force_x", [](auto& b) -> auto& { return b.force.viscous.x; });
  f(
      "viscous_force_y", [](auto& b) -> auto& { return b.force.viscous.y; });
  f(
      "normal", [](auto& b) -> auto& { return b.normal; });
  f(
      "along", [](auto& b) -> auto& { return b.along; });
}
}  // namespace

void save_history(StateWriter& out, const std::vector<BodySample>& history) {
  std::vector<double> column(history.size());
  for_each_history_column([&](const char* name, auto get) {
    for (std::size_t k = 0; k < history.size(); ++k) column[k] = get(history[k]);
    out.field(std::string("body_history_") + name, {column.data()}, column.size());
  });
}

std::vector<BodySample> load_history(StateReader& in) {
  std::vector<BodySample> history(in.count("body_history_time"));
  std::vector<double> column(history.size());
  for_each_history_column([&](const char* name, auto get) {
    in.field(std::string("body_history_") + name, {column.data()}, column.size());
    for (std::size_t k = 0; k < history.size(); ++k) get(history[k]) = column[k];
  });
  return history;
}

}  // namespace wcmps
