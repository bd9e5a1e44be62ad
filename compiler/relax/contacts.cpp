#include "relax/contacts.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "parallel.hpp"

namespace knitc::relax {

void closest_points(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0, const glm::dvec3& q1, double& s,
                    double& t) {
  const glm::dvec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  const double tiny = 1e-18;
  if (a <= tiny && e <= tiny) {
    s = t = 0.0;
    return;
  }
  if (a <= tiny) {
    s = 0.0;
    t = std::clamp(f / e, 0.0, 1.0);
    return;
  }
  const double c = glm::dot(d1, r);
  if (e <= tiny) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
    return;
  }
  const double b = glm::dot(d1, d2), denom = a * e - b * b;
  s = denom > tiny ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
}

// Where two segments cross seen from the face (their xy projections meet, half-open as
// measure::crossings counts them): the parameters along each. False if they do not.
bool Contacts::crossing(const Chains& c, const Pair& p, double& s, double& t) const {
  const glm::dvec3 offset = shift(p);
  const glm::dvec2 a0(c.pos[p.a]), ra = glm::dvec2(c.pos[p.a + 1]) - a0;
  const glm::dvec2 b0 = glm::dvec2(c.pos[p.b] + offset), rb = glm::dvec2(c.pos[p.b + 1] + offset) - b0;
  const double denom = ra.x * rb.y - ra.y * rb.x;
  if (std::abs(denom) < 1e-12 * (glm::dot(ra, ra) + glm::dot(rb, rb))) return false;
  const glm::dvec2 ab = b0 - a0;
  s = (ab.x * rb.y - ab.y * rb.x) / denom;
  t = (ab.x * ra.y - ab.y * ra.x) / denom;
  return s >= 0.0 && s < 1.0 && t >= 0.0 && t < 1.0;
}

std::int8_t Contacts::side_of(const Chains& c, const Pair& p) const {
  if (round_) return 0;
  double s, t;
  if (!crossing(c, p, s, t)) return 0;
  const double za = glm::mix(c.pos[p.a].z, c.pos[p.a + 1].z, s), zb = glm::mix(c.pos[p.b].z, c.pos[p.b + 1].z, t);
  return za > zb ? 1 : za < zb ? -1 : 0;
}

double Contacts::separation(const Chains& c, const Pair& p, glm::dvec3& push, double& s, double& t) const {
  const glm::dvec3 offset = shift(p);
  if (p.side != 0) {
    // A crossing must keep its yarn in front: if the one behind has come through, it goes
    // back straight along the fabric's normal, from where they cross.
    double cs, ct;
    if (crossing(c, p, cs, ct)) {
      const double za = glm::mix(c.pos[p.a].z, c.pos[p.a + 1].z, cs), zb = glm::mix(c.pos[p.b].z, c.pos[p.b + 1].z, ct);
      const double ahead = p.side * (za - zb);
      if (ahead <= 0.0) {
        s = cs, t = ct;
        push = glm::dvec3(0.0, 0.0, p.side);
        return ahead;
      }
    }
  }
  const glm::dvec3 &a0 = c.pos[p.a], &a1 = c.pos[p.a + 1];
  const glm::dvec3 b0 = c.pos[p.b] + offset, b1 = c.pos[p.b + 1] + offset;
  closest_points(a0, a1, b0, b1, s, t);
  push = glm::mix(a0, a1, s) - glm::mix(b0, b1, t);
  const double dist = glm::length(push);
  if (dist > 1e-12) {
    push /= dist;
  } else {  // touching centrelines and no side: part them the way they lay in the layout
    push = glm::mix(c.rest[p.a], c.rest[p.a + 1], s) - glm::mix(c.rest[p.b], c.rest[p.b + 1], t) - offset;
    push = glm::length(push) > 1e-12 ? glm::normalize(push) : glm::dvec3(0.0, 0.0, 1.0);
  }
  return dist;
}

const Contacts::Pair* Contacts::listed(const Pair& key) const {
  const auto again = std::lower_bound(extra_.begin(), extra_.end(), key, key_before);
  if (again != extra_.end() && !key_before(key, *again)) return &*again;
  const auto it = std::lower_bound(by_segments_.begin(), by_segments_.end(), key,
                                   [&](std::uint32_t x, const Pair& y) { return key_before(pairs_[x], y); });
  if (it == by_segments_.end()) return nullptr;
  const Pair& q = pairs_[*it];
  return !key_before(key, q) && !(q.held & dead) ? &q : nullptr;
}

std::int8_t Contacts::neighbours_side(const Pair& p) const {
  for (int da = -1; da <= 1; ++da)
    for (int db = -1; db <= 1; ++db) {
      if ((da == 0 && db == 0) || (da < 0 && p.a == 0) || (db < 0 && p.b == 0)) continue;
      const Pair key{static_cast<std::uint32_t>(static_cast<int>(p.a) + da), static_cast<std::uint32_t>(static_cast<int>(p.b) + db),
                     p.sx, p.sy, 0, 0, 0.0f, 0.0f};
      const Pair* q = listed(key);
      if (q && q->side != 0) return q->side;
    }
  return 0;
}

double Contacts::gap(const Chains& c, const Pair& p) const {
  glm::dvec3 push;
  double s, t;
  return separation(c, p, push, s, t) - p.reach;
}

double Contacts::push_apart(Chains& c, double skin, double scale, double shells, Strain* strain) {
  auto push = [&](Pair& p, double& deepest, Strain& asked) {
    if (p.held & dead) return;
    const std::size_t a = p.a, b = p.b;
    const glm::dvec3 offset = shift(p);
    const double reach = p.reach;
    // Most listed pairs are not touching: two spheres around the segments tell at once.
    const glm::dvec3 ha = 0.5 * (c.pos[a + 1] - c.pos[a]), hb = 0.5 * (c.pos[b + 1] - c.pos[b]);
    const glm::dvec3 between = (c.pos[a] + ha) - (c.pos[b] + hb + offset);
    const double shell = reach + shells * (p.shell - reach);  // the shells' surfaces, as far out as they have grown
    const double bound = std::max(shell, reach * (1.0 + skin)) + std::sqrt(glm::dot(ha, ha)) + std::sqrt(glm::dot(hb, hb));
    if (glm::dot(between, between) > bound * bound) return;
    double s, t;
    glm::dvec3 normal;
    const double dist = separation(c, p, normal, s, t);
    // A crossing's side is remembered from the first sweep the two cross seen from the
    // face, or taken over from a neighbouring pair that crossed before: the crossing has
    // slid along the yarn (a push may move it a segment at once). Kept from then on.
    if (p.side == 0 && dist > 0.0 && (p.side = side_of(c, p)) != 0) {
      const std::int8_t before = neighbours_side(p);
      if (before != 0) p.side = before;
    }
    const double target = reach * (1.0 + skin) * scale;
    deepest = std::max(deepest, reach - dist);
    // Past the cores, the shells: pressure (h0 / h)^p - 1 of the thickness h left of h0,
    // a step of it a sweep, never past the free surfaces.
    double goal = target;
    if (dist >= target) {
      if (shells <= 0.0 || dist >= shell) return;
      const double h0 = shell - reach, h = dist - reach;
      goal = dist + std::min(shell_rate * h0 * (std::pow(h0 / h, shell_exponent) - 1.0), shell - dist);
    }
    const double w[4] = {p.held & 1 ? 0.0 : 1.0 - s, p.held & 2 ? 0.0 : s, p.held & 4 ? 0.0 : 1.0 - t, p.held & 8 ? 0.0 : t};
    const double sum = (1.0 - s) * w[0] + s * w[1] + (1.0 - t) * w[2] + t * w[3];
    if (sum > 0.0) {
      const double lambda = (goal - dist) / sum;
      if (strain) asked.add((goal - dist) * normal, std::max(dist, 0.0) * normal);
      c.pos[a] += lambda * w[0] * normal;
      c.pos[a + 1] += lambda * w[1] * normal;
      c.pos[b] -= lambda * w[2] * normal;
      c.pos[b + 1] -= lambda * w[3] * normal;
    }
  };
  double first_deepest = 0.0;
  Strain first_asked;
  for (Pair& p : extra_) push(p, first_deepest, first_asked);
  const std::size_t strips = strip_first_.size() - 1;
  std::vector<double> per_strip(strips, 0.0);
  std::vector<Strain> strain_per_strip(strain ? strips : 0);
  for (std::size_t colour = 0; colour < 4; ++colour) {
    const std::size_t count = strips > colour ? (strips - colour + 3) / 4 : 0;
    parallel_for(count, threads_, [&](std::size_t j) {
      const std::size_t k = colour + 4 * j;
      double deepest = 0.0;  // locals: neighbouring strips' slots share a cache line
      Strain asked;
      for (std::size_t i = strip_first_[k]; i < strip_first_[k + 1]; ++i) push(pairs_[i], deepest, asked);
      per_strip[k] = deepest;
      if (strain) strain_per_strip[k] = asked;
    });
  }
  double deepest = 0.0;
  Strain asked;
  for (std::size_t i = across_first_; i < pairs_.size(); ++i) push(pairs_[i], deepest, asked);
  for (double d : per_strip) deepest = std::max(deepest, d);
  deepest = std::max(deepest, first_deepest);
  if (strain) strain->add(first_asked);
  if (strain) {  // summed in strip order: the same for any thread count
    for (const Strain& s : strain_per_strip) strain->add(s);
    strain->add(asked);
  }
  return deepest;
}

double Contacts::deepest(const Chains& c) const {
  double worst = 0.0;
  for (const auto* list : {&pairs_, &extra_})
    for (const Pair& p : *list)
      if (!(p.held & dead)) worst = std::max(worst, -gap(c, p));
  return worst;
}

double Contacts::compression(const Chains& c) const {
  double sum = 0.0;
  std::size_t pressed = 0;
  for (const auto* list : {&pairs_, &extra_})
    for (const Pair& p : *list) {
      if (p.held & dead) continue;
      const double dist = gap(c, p) + p.reach;
      if (dist >= p.shell) continue;
      sum += 1.0 - std::max(0.0, dist - p.reach) / (p.shell - p.reach);
      ++pressed;
    }
  return pressed > 0 ? sum / static_cast<double>(pressed) : 0.0;
}

void Contacts::moved(const std::function<void(glm::dvec3&)>& move, glm::dvec2 growth) {
  for (auto& p : built_at_) move(p);
  period_ *= growth;
  // The move scales each axis about a centre (relax.cpp, boost_size): where the grid's
  // points are now follows from where it takes the origin and the axes' unit points.
  glm::dvec3 origin(0.0), scale(1.0);
  move(origin);
  for (int axis = 0; axis < 3; ++axis) {
    glm::dvec3 unit(0.0);
    unit[axis] = 1.0;
    move(unit);
    scale[axis] = unit[axis] - origin[axis];
  }
  grid_offset_ = scale * grid_offset_ + origin;
  grid_scale_ *= scale;
}

}  // namespace knitc::relax
