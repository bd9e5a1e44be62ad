#include "relax/relax.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <optional>
#include <span>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "parallel.hpp"
#include "relax/press.hpp"
#include "relax/chains.hpp"
#include "relax/contacts.hpp"
#include "relax/repeat.hpp"

namespace knitc::relax {

namespace {

// The yarn's own terms, each a sweep along the chains.

// A piece of at least 4 spans of this many points is worked span by span (each_piece).
constexpr std::size_t span_points = 16384;

// A stretch of the chains' points, [from, to).
struct Range {
  std::size_t from, to;
};

// Calls step(i) for i from r.from + lo to r.to - hi - 1 of each range, ascending (or
// descending, `down`), in the order of each range's own walk. Each step of a sweep waits
// on the last (it moves the point the next one reads), so one walk is bound by its
// latency; four disjoint ranges are walked side by side, which the core overlaps. Each
// range's steps are the same operations in the same order: the same bits.
template <class Step>
void walk(std::span<const Range> ranges, std::size_t lo, std::size_t hi, bool down, Step&& step) {
  constexpr std::size_t side_by_side = 4;
  auto length = [&](const Range& r) { return r.to > r.from + lo + hi ? r.to - r.from - lo - hi : std::size_t{0}; };
  for (std::size_t g = 0; g < ranges.size(); g += side_by_side) {
    const auto group = ranges.subspan(g, std::min(side_by_side, ranges.size() - g));
    std::size_t longest = 0;
    for (const Range& r : group) longest = std::max(longest, length(r));
    for (std::size_t t = 0; t < longest; ++t)
      for (const Range& r : group)
        if (t < length(r)) step(down ? r.to - hi - 1 - t : r.from + lo + t);
  }
}

// Calls work(ranges) with each piece's points as a range; the pieces touch no point of
// another's, so they go in parallel (blocks of pieces about equal in points), unless a
// strain is summed, whose sum must keep one order (then one range a call, in order). A
// piece of 4 spans or more (a large fabric knitted from one yarn, a machine program's) is
// cut into spans that run on `overlap` points into the next (1: every segment, for the
// lengths; 2: every middle of three points, for bending): the even spans go in parallel
// with the short pieces, then the odd ones, so no two at once touch a point, and a call's
// ranges never touch each other's points. The spans depend on the piece alone: the result
// is the same for any thread count.
template <class Work>
void each_piece(const Chains& c, int threads, const Strain* strain, std::size_t overlap, Work&& work) {
  const std::size_t pieces = c.first.size() - 1;
  auto piece_range = [&](std::size_t piece) { return Range{c.first[piece], c.first[piece + 1]}; };
  if (strain) {
    for (std::size_t piece = 0; piece < pieces; ++piece) {
      const Range r = piece_range(piece);
      work(std::span<const Range>(&r, 1));
    }
    return;
  }
  std::vector<Range> even, odd;  // the long pieces' spans
  std::vector<Range> short_pieces;
  for (std::size_t piece = 0; piece < pieces; ++piece) {
    const std::size_t from = c.first[piece], to = c.first[piece + 1], points = to - from;
    const std::size_t spans = points / span_points;
    if (spans < 4) {
      short_pieces.push_back(piece_range(piece));
      continue;
    }
    for (std::size_t k = 0; k < spans; ++k)
      (k % 2 == 0 ? even : odd).push_back({from + points * k / spans, std::min(to, from + points * (k + 1) / spans + overlap)});
  }
  if (even.empty() && (threads <= 1 || pieces < 2)) {  // nothing to share out
    work(std::span<const Range>(short_pieces));
    return;
  }
  // The short pieces in blocks about equal in points, then the even spans four to a
  // call: one phase.
  const std::size_t wanted = std::min<std::size_t>(short_pieces.size(), 4 * static_cast<std::size_t>(std::max(threads, 1)));
  std::vector<std::size_t> block_first(wanted + 1, short_pieces.size());  // into short_pieces
  if (wanted > 0) {
    std::size_t total = 0;
    for (const Range& r : short_pieces) total += r.to - r.from;
    for (std::size_t b = 0, k = 0, seen = 0; b < wanted; ++b) {
      while (k < short_pieces.size() && seen < total * b / wanted) seen += short_pieces[k].to - short_pieces[k].from, ++k;
      block_first[b] = k;
    }
  }
  constexpr std::size_t spans_a_call = 4;
  auto calls = [&](const std::vector<Range>& spans) { return (spans.size() + spans_a_call - 1) / spans_a_call; };
  auto spans_of = [&](const std::vector<Range>& spans, std::size_t call) {
    const std::size_t from = call * spans_a_call;
    return std::span<const Range>(spans).subspan(from, std::min(spans_a_call, spans.size() - from));
  };
  parallel_for(wanted + calls(even), threads, [&](std::size_t u) {
    if (u >= wanted) return work(spans_of(even, u - wanted));
    work(std::span<const Range>(short_pieces).subspan(block_first[u], block_first[u + 1] - block_first[u]));
  });
  parallel_for(calls(odd), threads, [&](std::size_t u) { work(spans_of(odd, u)); });
}

// Every segment back to its length: a sweep up each chain, then one down, so a
// correction travels the whole yarn in one call rather than a segment per call.
void keep_lengths(Chains& c, int threads, Strain* strain = nullptr) {
  auto keep = [&](std::size_t i) {
    if (!c.segment[i]) return;
    const double wa = c.inv_mass[i], wb = c.inv_mass[i + 1];
    if (wa + wb <= 0.0) return;
    glm::dvec3 d = c.pos[i + 1] - c.pos[i];
    const double length = glm::length(d);
    if (length < 1e-12) return;
    if (strain) strain->add(-(length - c.rest_length[i]) / length * d, d);
    d *= (length - c.rest_length[i]) / (length * (wa + wb));
    c.pos[i] += wa * d;
    c.pos[i + 1] -= wb * d;
  };
  if (strain) {  // all up, then all down: the strain summed in one order
    for (std::size_t i = 0; i + 1 < c.pos.size(); ++i) keep(i);
    for (std::size_t i = c.pos.size(); i-- > 1;) keep(i - 1);
    return;
  }
  each_piece(c, threads, strain, 1, [&](std::span<const Range> ranges) {
    walk(ranges, 0, 1, false, keep);
    walk(ranges, 0, 1, true, keep);
  });
}

// Bending: an elastic rod whose rest shape is straight. Every three consecutive points
// move `stiffness` (in (0, 1]) of the way to their chord's line, the middle one toward
// the neighbours' midpoint and the neighbours away, keeping their centroid: a step down
// the gradient of the squared second differences, the discrete rod's bending energy.
// Held lengths and contacts stop it; what is left opens the loops.
void bend(Chains& c, double stiffness, int threads, Strain* strain = nullptr) {
  each_piece(c, threads, strain, 2, [&](std::span<const Range> ranges) {
    walk(ranges, 1, 1, false, [&](std::size_t i) {
      const glm::dvec3 second = c.pos[i - 1] + c.pos[i + 1] - 2.0 * c.pos[i];
      const double wi = c.inv_mass[i], wa = c.inv_mass[i - 1], wb = c.inv_mass[i + 1];
      const double sum = 4.0 * wi + wa + wb;  // the constraint's gradient (1, -2, 1), squared, by mobility
      if (sum <= 0.0) return;
      const glm::dvec3 step = (stiffness / sum) * second;
      // (A periodic repeat's size: the step's change of the two segments, by each.)
      if (strain) {
        strain->add((2.0 * wi + wa) * step, c.pos[i] - c.pos[i - 1]);
        strain->add(-(2.0 * wi + wb) * step, c.pos[i + 1] - c.pos[i]);
      }
      c.pos[i] += 2.0 * wi * step;
      c.pos[i - 1] -= wa * step;
      c.pos[i + 1] -= wb * step;
    });
  });
}

// No bend tighter than `radii` tube radii: where the circle through a point and its two
// neighbours is smaller, the point moves toward their chord and the neighbours away,
// keeping the three points' centroid.
void limit_bends(Chains& c, double radii, int threads) {
  each_piece(c, threads, nullptr, 2, [&](std::span<const Range> ranges) {
    walk(ranges, 1, 1, false, [&](std::size_t i) {
      const glm::dvec3 mid = 0.5 * (c.pos[i - 1] + c.pos[i + 1]);
      const double half_chord = 0.5 * glm::distance(c.pos[i - 1], c.pos[i + 1]);
      const double rise = glm::distance(c.pos[i], mid);
      const double radius = radii * c.shell[i];
      // The circle through the three points has radius (half_chord^2 + rise^2) / (2 rise).
      if (rise <= 1e-12 || half_chord * half_chord + rise * rise <= 2.0 * rise * radius) return;
      const double allowed = half_chord < radius ? radius - std::sqrt(radius * radius - half_chord * half_chord) : radius;
      const glm::dvec3 move = (mid - c.pos[i]) * ((rise - std::min(allowed, rise)) / rise);
      const double wi = c.inv_mass[i], wa = c.inv_mass[i - 1], wb = c.inv_mass[i + 1];
      const double sum = wi + 0.25 * (wa + wb);
      if (sum <= 0.0) return;
      c.pos[i] += (wi / sum) * move;
      c.pos[i - 1] -= (0.5 * wa / sum) * move;
      c.pos[i + 1] -= (0.5 * wb / sum) * move;
    });
  });
}

// The sweeps move the fabric as a whole only slowly: a swatch that must draw in by a
// few percent to find the length its yarn needs around the contacts does so from its
// edges inward, over as many sweeps as it has courses. So the part of a sweep's motion
// that changes the swatch's width (flat: x about the centre; round: the tube's radius)
// or height (y) is fitted by least squares and carried further, `boost` times (per
// axis) more, as a two-level solver corrects its coarsest modes. At the fixed point the
// sweeps move nothing, and neither does this: the answer is the sweeps' own.
struct Size {
  bool round = false;
  bool free_width = true, free_height = true;
  // A periodic axis has no edges to draw in from: its size follows the strain the sweep's
  // contacts and lengths asked for (pressure against tension), not the motion.
  bool periodic_width = false, periodic_height = false;
  glm::dvec2 boost{0.0};     // now, per axis
  glm::dvec2 most{0.0};      // the largest it may grow to
  glm::dvec2 last_sign{0.0}; // the sign of the last sweep's motion, per axis
  glm::dvec2 mean_strain{0.0};  // periodic: the running mean of the strain asked
};

// The boost adapts as in resilient propagation (Riedmiller and Braun): it grows while the
// motion keeps its sign and falls back to 1 when it turns (quartering it left a tube's
// height overshooting for hundreds of sweeps once the lengths held firmly), so a fabric
// drawing in steadily is carried fast and one that has found its size (the bending and
// the contacts balanced) is not thrown back and forth.
double adapt(double motion, double& boost, double most, double& last_sign) {
  const double sign = motion > 0.0 ? 1.0 : motion < 0.0 ? -1.0 : 0.0;
  if (sign * last_sign > 0.0)
    boost = std::min(most, boost * 1.5);
  else if (sign * last_sign < 0.0)
    boost = 1.0;
  last_sign = sign;
  return boost * motion;
}

void boost_size(Chains& c, const std::vector<glm::dvec3>& before, Size& size, const Strain& asked, Contacts& contacts) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const auto& p : c.pos) {
    lo = glm::min(lo, glm::dvec2(p));
    hi = glm::max(hi, glm::dvec2(p));
  }
  const glm::dvec2 centre = 0.5 * (lo + hi);
  auto across = [&](const glm::dvec3& p) { return size.round ? glm::dvec2(p.x, p.z) : glm::dvec2(p.x - centre.x, 0.0); };
  double wn = 0.0, wd = 0.0, hn = 0.0, hd = 0.0;
  for (std::size_t i = 0; i < c.pos.size(); ++i) {
    if (c.inv_mass[i] == 0.0) continue;
    const glm::dvec2 w = across(before[i]), moved = across(c.pos[i]) - w;
    wn += glm::dot(moved, w);
    wd += glm::dot(w, w);
    const double h = before[i].y - centre.y;
    hn += (c.pos[i].y - before[i].y) * h;
    hd += h * h;
  }
  double grow_w = size.free_width && wd > 0.0 ? std::clamp(adapt(wn / wd, size.boost.x, size.most.x, size.last_sign.x), -0.01, 0.01) : 0.0;
  double grow_h = size.free_height && hd > 0.0 ? std::clamp(adapt(hn / hd, size.boost.y, size.most.y, size.last_sign.y), -0.01, 0.01) : 0.0;
  // A periodic repeat's strain, too, is carried further while it keeps its sign (a rib
  // draws in over hundreds of sweeps); it is noisy from sweep to sweep (a contact list
  // rebuilt, a crossing pushed back), so its sign is read from a running mean.
  auto periodic_growth = [&](double stretch, double lever, double& mean, double& boost, double most, double& last_sign) {
    if (lever <= 0.0) return 0.0;
    const double strain = stretch / lever;
    mean = 0.8 * mean + 0.2 * strain;
    adapt(mean, boost, most, last_sign);
    return std::clamp(boost * strain, -0.01, 0.01);
  };
  if (size.periodic_width)
    grow_w = periodic_growth(asked.stretch.x, asked.lever.x, size.mean_strain.x, size.boost.x, size.most.x, size.last_sign.x);
  if (size.periodic_height)
    grow_h = periodic_growth(asked.stretch.y, asked.lever.y, size.mean_strain.y, size.boost.y, size.most.y, size.last_sign.y);
  if (grow_w == 0.0 && grow_h == 0.0) return;
  auto move = [&](glm::dvec3& p) {
    if (size.round) {
      p.x *= 1.0 + grow_w;
      p.z *= 1.0 + grow_w;
    } else {
      p.x += grow_w * (p.x - centre.x);
    }
    p.y += grow_h * (p.y - centre.y);
  };
  for (std::size_t i = 0; i < c.pos.size(); ++i)
    if (c.inv_mass[i] != 0.0) move(c.pos[i]);
  contacts.moved(move, glm::dvec2(1.0 + grow_w, 1.0 + grow_h));
}

// The mean distance the free points on loops moved since `before`: the fabric's own
// motion (a tail straightening behind it does not count, nor held points).
double mean_move(const Chains& c, const std::vector<glm::dvec3>& before) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < c.pos.size(); ++i)
    if (c.on_loop[i] && c.inv_mass[i] != 0.0) {
      sum += glm::distance(c.pos[i], before[i]);
      ++n;
    }
  return n ? sum / static_cast<double>(n) : 0.0;
}

double polyline_length(const std::vector<glm::dvec3>& p, std::size_t from, std::size_t to) {
  double length = 0.0;
  for (std::size_t i = from + 1; i < to; ++i) length += glm::distance(p[i - 1], p[i]);
  return length;
}

// The largest relative change of a piece's length from its chain's rest lengths, >= 0.
double length_change(const Chains& c) {
  double worst = 0.0;
  for (std::size_t i = 0; i + 1 < c.first.size(); ++i) {
    const std::size_t from = c.first[i], to = c.first[i + 1];
    double rest = 0.0;
    for (std::size_t k = from; k + 1 < to; ++k) rest += c.rest_length[k];
    if (rest > 0.0) worst = std::max(worst, std::abs(polyline_length(c.pos, from, to) / rest - 1.0));
  }
  return worst;
}

}  // namespace

std::vector<std::vector<std::uint32_t>> same_as_by_piece(const std::vector<yarn_paths::Piece>& pieces,
                                                         const std::vector<std::uint32_t>& same_as) {
  std::vector<std::vector<std::uint32_t>> out(same_as.empty() ? 0 : pieces.size());
  std::size_t offset = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::size_t n = pieces[i].data_points.size();
    out[i].resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t g = same_as[offset + k];
      out[i][k] = g >= offset && g < offset + n ? static_cast<std::uint32_t>(g - offset) : static_cast<std::uint32_t>(k);
    }
    offset += n;
  }
  assert(same_as.empty() || offset == same_as.size());
  return out;
}

Relaxed relax(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& pieces, const std::vector<yarn::Size>& sizes,
              const Options& options) {
  auto relaxed = [&]() -> Relaxed {
    if (options.by_repeat && options.boundary == Boundary::free) {
      // The repeat's lattice: the layout's, or a copy stepping as its needle positions do.
      const double step = lattice_step(layout);
      std::optional<layout::Layout> narrower;
      if (step != layout.loop_width) {
        narrower = layout;
        narrower->loop_width = step;
      }
      const layout::Layout& lattice = narrower ? *narrower : layout;
      if (const auto repeat = find_repeat(lattice))
        if (auto out = relax_by_repeat(lattice, pieces, sizes, options, *repeat)) return std::move(*out);
    }
    return relax_chains(layout, pieces, sizes, options, nullptr);  // a copy: a garment's repeat reads them only
  };
  Relaxed out = relaxed();
  if (options.pressed) press(out.pieces, sizes, thread_count(options.threads), out.same_as);
  return out;
}

Relaxed relax_chains(const layout::Layout& layout, std::vector<yarn_paths::Piece> pieces, const std::vector<yarn::Size>& sizes,
                     const Options& options, const Start* start) {
  Relaxed out;
  Chains c = chains_of(layout, pieces, sizes, options.boundary);
  const double d = c.thickest_core;
  if (d <= 0.0 || c.pos.empty()) {
    out.pieces = std::move(pieces);
    return out;
  }
  if (start)
    for (const Image& image : start->images)
      if (image.across != 0)
        c.along_period[c.piece[image.point]] = (c.along[image.source] - c.along[image.point]) / -image.across;
  const bool held_interior = start && !start->held.empty();
  const int carried = held_interior && !start->from.empty() ? std::max(1, start->morph_sweeps) : 0;  // sweeps
  if (held_interior) {
    assert(start->pos.size() == c.pos.size() && start->held.size() == c.pos.size());
    assert(carried == 0 || start->from.size() == c.pos.size());
    c.pos = carried > 0 ? start->from : start->pos;
    for (std::size_t i = 0; i < c.pos.size(); ++i)
      if (start->held[i]) c.inv_mass[i] = 0.0;
  }
  glm::dvec2 period(0.0);
  if (options.boundary == Boundary::periodic) {
    // Flat work: across, one loop width a wale; up, one course spacing a course, so the
    // cast-on's loops stand in (one repeat up) for the children of the last course's. The
    // repeat's size follows the strain its constraints ask for (see Size).
    if (layout.knitting == Knitting::flat)
      period = glm::dvec2(layout.wales * layout.loop_width,
                          layout.heights.empty() ? layout.courses * layout.course_spacing  // as always, to the bit
                                                 : layout::course_y(layout, layout.courses - 1) + layout.course_spacing);
  }
  if (start && (start->period.x > 0.0 || start->period.y > 0.0)) period = start->period;
  const int threads = thread_count(options.threads);
  Contacts contacts(period, contact_margin * c.thickest, layout.knitting == Knitting::round, threads);
  Size size;
  size.round = layout.knitting == Knitting::round;
  // Held edges keep the swatch's size, and a held interior (a tiled repeat's) keeps it too.
  size.free_width = size.free_height = options.boundary != Boundary::held && !held_interior;
  size.periodic_width = period.x > 0.0 && !held_interior;
  size.periodic_height = period.y > 0.0 && !held_interior;
  // About the number of loops between the swatch's middle and its edges, times a gain.
  size.most = size_gain * glm::dvec2(layout.wales, layout.courses);
  size.boost = glm::dvec2(1.0);

  contacts.find(c);
  out.stats.start_overlap = contacts.deepest(c) / d;
  const double tolerance = options.tolerance * d;
  const double closest = std::clamp(1.0 - out.stats.start_overlap, 0.0, 1.0);  // of the radii
  std::vector<glm::dvec3> before;
  int iteration = 0, cores_full_from = -1;
  for (; iteration < options.max_iterations; ++iteration) {
    if (iteration < carried) {  // the held points a step on toward the start's places, the last step exact
      const double t = static_cast<double>(iteration + 1) / static_cast<double>(carried);
      for (std::size_t i = 0; i < c.pos.size(); ++i)
        if (start->held[i]) c.pos[i] = iteration + 1 == carried ? start->pos[i] : start->from[i] + t * (start->pos[i] - start->from[i]);
    }
    if (contacts.stale(c)) contacts.find(c);
    before = c.pos;
    // The contacts' distance ramps up from the layout's closest approach to the yarns'
    // radii: a first sweep that pushed the interlocks fully apart at once would move
    // points by half a diameter, enough for a loop to slip out of the one it is pulled
    // through (seen on stranded colourwork: its parent's head and its feet part sideways).
    // Held edges keep the swatch's size: there the lengths step undoes partial pushes,
    // and the ramp would only put off the same full push.
    const double scale =
        options.boundary == Boundary::held ? 1.0 : std::min(1.0, closest + (1.0 - closest) * (iteration + 1) / ramp_sweeps);
    Strain asked;  // only a periodic repeat's size needs it
    Strain* strain = size.periodic_width || size.periodic_height ? &asked : nullptr;
    // The shells grow once the cores are at their full distance (ramp_sweeps).
    if (scale == 1.0 && cores_full_from < 0) cores_full_from = iteration;
    const double shells = cores_full_from < 0 ? 0.0 : std::min(1.0, (iteration - cores_full_from + 1.0) / ramp_sweeps);
    const double met = contacts.push_apart(c, contact_skin, scale, shells, strain);
    keep_lengths(c, threads, strain);
    bend(c, bending_stiffness, threads, strain);
    limit_bends(c, tightest_bend_radii, threads);
    for (int pass = 0; pass < length_passes; ++pass) keep_lengths(c, threads, strain);
    // Settled: this sweep's pushes small (a few tolerances, at full strength, shells grown) and its
    // loops moved by a small step on average since `before`.
    const bool pushes_settled = met <= settled_pushes * tolerance && iteration > 0 && scale == 1.0 && shells == 1.0;
    auto moved_little = [&] { return mean_move(c, before) <= options.settled_motion * d; };
    // Where the sweep's own passes have settled, what motion is left is theirs to the
    // size's fit too: carried further by a grown boost it would move the fabric on its
    // own (a tall strip's height kept one sign at 1e-10 a sweep, boosted to its cap it
    // moved the strip's ends 0.01 to 0.1 mm a sweep for 400 sweeps), so it starts again.
    if (pushes_settled && (size.free_width || size.free_height) && moved_little()) size.boost = glm::dvec2(1.0);
    boost_size(c, before, size, asked, contacts);
    if (start)
      for (const Image& image : start->images)
        c.pos[image.point] = c.pos[image.source] + glm::dvec3(image.across * contacts.period().x, 0.0, 0.0);
    // Done when the sweep settled, size step and all, it left no cores overlapping (the
    // list holds every pair that could, until it is stale) and the yarns have their
    // lengths back.
    if (pushes_settled && iteration + 1 >= carried && moved_little()) {
      if (contacts.stale(c)) contacts.find(c);
      // (Held edges keep the swatch's size, so its yarn cannot get its length back.)
      if (contacts.deepest(c) <= tolerance && (!size.free_height || length_change(c) <= settled_length)) {
        ++iteration;
        break;
      }
    }
  }
  if (contacts.stale(c)) contacts.find(c);
  out.stats.iterations = iteration;
  out.stats.period = contacts.period();
  out.stats.end_overlap = contacts.deepest(c) / d;
  out.stats.compression = contacts.compression(c);
  out.stats.length_change = length_change(c);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const std::size_t from = c.first[i], to = c.first[i + 1];
    std::copy(c.pos.begin() + static_cast<std::ptrdiff_t>(from), c.pos.begin() + static_cast<std::ptrdiff_t>(to),
              pieces[i].data_points.begin());
  }
  out.pieces = std::move(pieces);
  return out;
}

}  // namespace knitc::relax
