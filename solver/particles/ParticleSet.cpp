#include "particles/ParticleSet.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "core/Parallel.h"

namespace wcmps {

void ParticleState::resize(std::size_t count) {
  x.assign(count, 0.0);
  y.assign(count, 0.0);
  u.assign(count, 0.0);
  v.assign(count, 0.0);
  p.assign(count, 0.0);
  n.assign(count, 0.0);
  surface.assign(count, 0);
}

void ParticleState::swap(ParticleState& o) noexcept {
  x.swap(o.x);
  y.swap(o.y);
  u.swap(o.u);
  v.swap(o.v);
  shift_u.swap(o.shift_u);
  shift_v.swap(o.shift_v);
  struck_n.swap(o.struck_n);
  rest_a.swap(o.rest_a);
  rest_b.swap(o.rest_b);
  p.swap(o.p);
  n.swap(o.n);
  surface.swap(o.surface);
}

void ParticleSet::track_shift() {
  for (ParticleState* s : {&now, &next}) {
    s->shift_u.assign(kind.size(), 0.0);
    s->shift_v.assign(kind.size(), 0.0);
  }
}

void ParticleSet::track_strikes() {
  for (ParticleState* s : {&now, &next}) s->struck_n.assign(kind.size(), 0.0);
}

void ParticleSet::track_rest_shape() {
  for (ParticleState* s : {&now, &next}) {
    s->rest_a.assign(kind.size(), std::numeric_limits<double>::quiet_NaN());
    s->rest_b.assign(kind.size(), std::numeric_limits<double>::quiet_NaN());
  }
}

ParticleSet::ParticleSet(const std::vector<ParticleSeed>& walls,
                         const std::vector<ParticleSeed>& ghosts,
                         const std::vector<std::int32_t>& ghost_sources,
                         const std::vector<ParticleSeed>& fluid)
    : wall_end_(static_cast<std::int64_t>(walls.size())),
      fluid_begin_(static_cast<std::int64_t>(walls.size() + ghosts.size())),
      ghost_source_(ghost_sources) {
  if (ghost_sources.size() != ghosts.size()) {
    throw std::invalid_argument("ParticleSet: one ghost source per ghost particle is needed");
  }
  const std::size_t total = walls.size() + ghosts.size() + fluid.size();
  now.resize(total);
  kind.resize(total);
  id.resize(total);
  id_scratch_.resize(total);
  std::size_t k = 0;
  normal_x.resize(static_cast<std::size_t>(fluid_begin_));
  normal_y.resize(static_cast<std::size_t>(fluid_begin_));
  auto place = [&](const std::vector<ParticleSeed>& seeds, ParticleKind what) {
    for (const auto& s : seeds) {
      if (what != ParticleKind::Fluid) {
        normal_x[k] = s.normal.x;
        normal_y[k] = s.normal.y;
      }
      now.x[k] = s.position.x;
      now.y[k] = s.position.y;
      now.u[k] = s.velocity.x;
      now.v[k] = s.velocity.y;
      kind[k] = what;
      id[k] = static_cast<std::int32_t>(k);
      ++k;
    }
  };
  place(walls, ParticleKind::Wall);
  place(ghosts, ParticleKind::Ghost);
  place(fluid, ParticleKind::Fluid);
  for (auto src : ghost_source_) {
    if (src < 0 || src >= wall_end_) {
      throw std::invalid_argument("ParticleSet: ghost source is not a wall particle");
    }
  }
  next = now;
}

void ParticleSet::reorder_fluid(const std::vector<std::int32_t>& order) {
  const std::int64_t b = fluid_begin_;
  if (static_cast<std::int64_t>(order.size()) != size() - b) {
    throw std::invalid_argument("reorder_fluid: order must list every fluid particle once");
  }
  // Boundary particles keep their slots; copy them so that `next` is a complete state.
  std::copy_n(now.p.begin(), b, next.p.begin());
  std::copy_n(now.n.begin(), b, next.n.begin());
  std::copy_n(now.surface.begin(), b, next.surface.begin());
  parallel_for(0, size() - b, [&](std::int64_t k) {
    const std::int64_t from = order[k];
    const std::int64_t to = b + k;
    next.x[to] = now.x[from];
    next.y[to] = now.y[from];
    next.u[to] = now.u[from];
    next.v[to] = now.v[from];
    next.p[to] = now.p[from];
    next.n[to] = now.n[from];
    next.surface[to] = now.surface[from];
    id_scratch_[to] = id[from];
  });
  if (!now.shift_u.empty()) {
    parallel_for(0, size() - b, [&](std::int64_t k) {
      next.shift_u[b + k] = now.shift_u[order[k]];
      next.shift_v[b + k] = now.shift_v[order[k]];
    });
  }
  if (!now.struck_n.empty()) {
    parallel_for(0, size() - b,
                 [&](std::int64_t k) { next.struck_n[b + k] = now.struck_n[order[k]]; });
  }
  if (!now.rest_a.empty()) {
    parallel_for(0, size() - b, [&](std::int64_t k) {
      next.rest_a[b + k] = now.rest_a[order[k]];
      next.rest_b[b + k] = now.rest_b[order[k]];
    });
  }
  now.swap(next);
  std::copy(id_scratch_.begin() + b, id_scratch_.end(), id.begin() + b);
}

}  // namespace wcmps
