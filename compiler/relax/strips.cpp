#include "relax/strips.hpp"
#include "relax/tiled_start.hpp"

#include "parallel.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include <glm/geometric.hpp>

namespace knitc::relax {

namespace {

int mod(int a, int b) { return ((a % b) + b) % b; }

// A block of loops, [c0, c1) x [w0, w1), periodic across (x: a band along a course,
// `wales` loops a period) or up (y: a selvedge's band, `courses` a period).
struct Block {
  int c0, c1, w0, w1;
  bool across;
};

struct Fabric {
  const layout::Layout& layout;
  const std::vector<yarn_paths::Piece>& chains;
  const LoopGrid& grid;
  std::vector<std::pair<long, long>> owner;  // per loop: its piece and its index there
  std::vector<std::size_t> first;            // per piece: its first point in start
};

// One strip: the block laid out alone, each piece's runs through it, where they start.
struct Strip {
  layout::Layout layout;
  std::vector<yarn_paths::Piece> runs;
  std::vector<std::size_t> run_piece, run_base;  // per run: the fabric's piece, and its point the run's first is
  std::vector<std::size_t> period_end;           // per run: where its image a period on starts (0: none)
  std::vector<long> block_loop;                   // per fabric loop: the block's loop, or -1
  std::vector<std::pair<std::size_t, std::size_t>> where;  // per block loop: run, loop
  Start start;
};

// The block's runs and start; false where the block's yarn does not run as a strip needs
// (across: each course's yarn running on periodically into the next period; up: every
// run entering and leaving the block through its held side).
bool make_strip(const Fabric& f, const Block& b, glm::dvec2 period, const Start& start, Strip& s) {
  const auto& layout = f.layout;
  s.layout.courses = b.c1 - b.c0;
  s.layout.wales = b.w1 - b.w0;
  s.layout.knitting = Knitting::flat;
  s.layout.loop_width = layout.loop_width;
  s.layout.course_spacing = layout.course_spacing;
  s.layout.float_behind = layout.float_behind;
  s.layout.float_in_front = layout.float_in_front;
  s.block_loop.assign(layout.loops.size(), -1);
  for (int c = b.c0; c < b.c1; ++c) {
    const auto C = static_cast<std::size_t>(c);
    s.layout.needle.push_back(b.w1 - b.w0);
    s.layout.origin_x.push_back(layout.origin_x[C]);
    const auto& edges = layout.slot_x[C];
    if (edges.size() < static_cast<std::size_t>(b.w1) + 1) return false;
    s.layout.slot_x.emplace_back(edges.begin() + b.w0, edges.begin() + b.w1 + 1);
    s.layout.direction.push_back(layout.direction[C]);
    for (int w = b.w0; w < b.w1; ++w) {
      const long l = f.grid(c, w);
      if (l < 0 || f.owner[static_cast<std::size_t>(l)].first < 0) return false;
      layout::Loop loop = layout.loops[static_cast<std::size_t>(l)];
      loop.course = c - b.c0;
      loop.wale = w - b.w0;
      s.block_loop[static_cast<std::size_t>(l)] = static_cast<long>(s.layout.loops.size());
      s.layout.loops.push_back(loop);
    }
  }
  s.where.assign(s.layout.loops.size(), {0, 0});
  const double width = (b.w1 - b.w0) * layout.loop_width;  // the period across, as laid out
  for (std::size_t i = 0; i < f.chains.size(); ++i) {
    const auto& piece = f.chains[i];
    auto course_of = [&](std::size_t j) { return layout.loops[static_cast<std::size_t>(piece.loops[j])].course; };
    auto inside = [&](std::size_t j) { return s.block_loop[static_cast<std::size_t>(piece.loops[j])] >= 0; };
    std::size_t j = 0;
    while (j < piece.loops.size()) {
      if (!inside(j)) {
        ++j;
        continue;
      }
      std::size_t end = j + 1;
      while (end < piece.loops.size() && inside(end) && (!b.across || course_of(end) == course_of(j))) ++end;
      std::size_t from = piece.loop_first[j], n = piece.loop_last[end - 1] + 1 - from, handles = 0;
      int across = 0;
      if (b.across) {
        // One period of the course's yarn and its images in the periods before and after,
        // kept there as it moves (as the tile's are).
        if (j == 0 || end >= piece.loops.size() || course_of(j - 1) != course_of(j) || course_of(end) != course_of(j)) return false;
        const std::size_t p = piece.loop_first[end] - from;
        across = periodic_run(piece.data_points, from, p, width, 1e-3 * layout.loop_width);
        if (across == 0) return false;
        n = p;
        handles = run_handles;
      } else {
        // A selvedge's run: in from the held interior, round the turn, back out into it.
        auto held = [&](std::size_t k) { return start.held[f.first[i] + piece.loop_first[k]] != 0; };
        if (!held(j) || !held(end - 1)) return false;
      }
      yarn_paths::Piece run;
      run.yarn = piece.yarn;
      const std::size_t base = from - handles;
      run.data_points.assign(piece.data_points.begin() + static_cast<std::ptrdiff_t>(base),
                             piece.data_points.begin() + static_cast<std::ptrdiff_t>(from + n + handles));
      const std::size_t r = s.runs.size(), at = s.start.pos.size();
      for (std::size_t k = j; k < end; ++k) {
        const auto bl = static_cast<std::size_t>(s.block_loop[static_cast<std::size_t>(piece.loops[k])]);
        s.where[bl] = {r, run.loops.size()};
        run.loops.push_back(static_cast<int>(bl));
        run.loop_first.push_back(piece.loop_first[k] - base);
        run.loop_last.push_back(piece.loop_last[k] - base);
      }
      for (std::size_t k = 0; k < run.data_points.size(); ++k) {
        s.start.pos.push_back(start.pos[f.first[i] + base + k]);
        s.start.held.push_back(start.held[f.first[i] + base + k]);
      }
      for (std::size_t h = 0; h < handles; ++h) {
        s.start.images.push_back({static_cast<std::uint32_t>(at + h), static_cast<std::uint32_t>(at + h + n), static_cast<std::int8_t>(-across)});
        s.start.images.push_back(
            {static_cast<std::uint32_t>(at + handles + n + h), static_cast<std::uint32_t>(at + handles + h), static_cast<std::int8_t>(across)});
      }
      s.runs.push_back(std::move(run));
      s.run_piece.push_back(i);
      s.run_base.push_back(base);
      s.period_end.push_back(handles > 0 ? handles + n : 0);
      j = end;
    }
  }
  s.start.period = b.across ? glm::dvec2(period.x, 0.0) : glm::dvec2(0.0, period.y);
  return !s.runs.empty();
}

// The relaxed strip's places copied to every target loop (band loops laid out as the
// block's loop a whole number of periods along), and held; each point placed listed in
// `out.copies` with its relaxed point's number, its run's first `numbered` on.
void copy_strip(const Fabric& f, const Block& b, glm::dvec2 period, const Strip& s, const std::vector<yarn_paths::Piece>& relaxed,
                const std::vector<int>& targets, Start& start, Strips& out) {
  std::vector<std::uint32_t> run_number(relaxed.size());
  for (std::size_t r = 0; r < relaxed.size(); ++r) {
    run_number[r] = out.numbered;
    out.numbered += static_cast<std::uint32_t>(relaxed[r].data_points.size());
  }
  const auto& layout = f.layout;
  const int P = b.w1 - b.w0, Q = b.c1 - b.c0;
  std::vector<std::uint8_t> is_target(layout.loops.size(), 0);
  for (const int target : targets) is_target[static_cast<std::size_t>(target)] = 1;
  for (const int target : targets) {
    const auto l = static_cast<std::size_t>(target);
    const auto& loop = layout.loops[l];
    const int bc = b.across ? loop.course : b.c0 + mod(loop.course - b.c0, Q);
    const int bw = b.across ? b.w0 + mod(loop.wale - b.w0, P) : loop.wale;
    const long block = f.grid(bc, bw);
    if (block < 0 || s.block_loop[static_cast<std::size_t>(block)] < 0 || f.owner[l].first < 0) continue;
    const auto [r, tj] = s.where[static_cast<std::size_t>(s.block_loop[static_cast<std::size_t>(block)])];
    const auto& piece = f.chains[static_cast<std::size_t>(f.owner[l].first)];
    const auto pj = static_cast<std::size_t>(f.owner[l].second);
    const auto& run = s.runs[r];
    const std::size_t fa = piece.loop_first[pj], tf = run.loop_first[tj];
    std::size_t n = piece.loop_last[pj] - fa;
    if (run.loop_last[tj] - tf != n) continue;
    const glm::dvec3 laid_step((loop.wale - bw) * layout.loop_width, (loop.course - bc) * layout.course_spacing, 0.0);
    const glm::dvec3 shift(b.across ? (loop.wale - bw) / P * period.x : 0.0, b.across ? 0.0 : (loop.course - bc) / Q * period.y, 0.0);
    auto alike = [&](std::size_t from, std::size_t to) {
      for (std::size_t k = from; k <= to; ++k)
        if (glm::distance(piece.data_points[fa + k], run.data_points[tf + k] + laid_step) > 1e-3 * layout.loop_width) return false;
      return true;
    };
    if (!alike(0, n)) continue;
    // On to the next loop's first point, where that loop is copied too (not a corner's,
    // which relaxes on) and the block's yarn has as many points there.
    const std::size_t next = tj + 1 < run.loops.size() ? run.loop_first[tj + 1] : s.period_end[r];
    if (pj + 1 < piece.loops.size() && is_target[static_cast<std::size_t>(piece.loops[pj + 1])] && next > tf + n &&
        next <= run.data_points.size() && piece.loop_first[pj + 1] - fa == next - tf && alike(n + 1, next - tf - 1))
      n = next - tf - 1;
    const std::size_t g = f.first[static_cast<std::size_t>(f.owner[l].first)] + fa;
    for (std::size_t k = 0; k <= n; ++k) {
      if (start.held[g + k]) continue;
      start.pos[g + k] = relaxed[r].data_points[tf + k] + shift;
      start.held[g + k] = 1;
      out.copies.emplace_back(static_cast<std::uint32_t>(g + k), run_number[r] + static_cast<std::uint32_t>(tf + k));
    }
  }
}

}  // namespace

Strips relax_strips(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& chains, const std::vector<yarn::Size>& sizes,
                    const Options& options, const Repeat& repeat, glm::dvec2 period, const LoopGrid& grid,
                    const std::vector<std::uint8_t>& loop_held, Start& start) {
  Strips out;
  const int C = grid.courses, W = grid.wales;
  auto held = [&](int c, int w) {
    const long l = grid(c, w);
    return l >= 0 && loop_held[static_cast<std::size_t>(l)] != 0;
  };
  // The bands' depths, read across the middle; then every loop must be held but for them.
  int B = 0, T = 0, L = 0, R = 0;
  while (B < C && !held(B, W / 2)) ++B;
  while (T < C && !held(C - 1 - T, W / 2)) ++T;
  while (L < W && !held(C / 2, L)) ++L;
  while (R < W && !held(C / 2, W - 1 - R)) ++R;
  constexpr int context = 2;  // held courses (wales) beside a strip's band
  if (B + T + 2 * context > C || L + R + 2 * context > W) return out;
  for (int c = 0; c < C; ++c)
    for (int w = 0; w < W; ++w) {
      if (grid(c, w) < 0) return out;
      const bool band = c < B || c >= C - T || w < L || w >= W - R;
      if (held(c, w) == band) return out;
    }

  Fabric f{layout, chains, grid, std::vector<std::pair<long, long>>(layout.loops.size(), {-1, -1}), {}};
  std::size_t at = 0;
  for (std::size_t i = 0; i < chains.size(); ++i) {
    f.first.push_back(at);
    at += chains[i].data_points.size();
    for (std::size_t j = 0; j < chains[i].loops.size(); ++j)
      f.owner[static_cast<std::size_t>(chains[i].loops[j])] = {static_cast<long>(i), static_cast<long>(j)};
  }
  const int P = repeat.wales, Q = repeat.courses;
  // A strip pays where its band runs on for a few periods past the corners.
  constexpr int least_periods = 4;
  Options strip_options = options;
  strip_options.by_repeat = false;
  strip_options.boundary = Boundary::free;
  // The strips, each a block and the loops it is copied onto. They lie apart (each band's
  // middle, its ends held), so each is laid out, checked and relaxed on its own thread,
  // then copied in order.
  struct Job {
    Block block;
    std::function<bool(int, int)> target;
    Strip strip;        // laid out already (an up strip's, chosen by laying it out), or not
    bool made = false;
  };
  std::vector<Job> jobs;
  // Across: a lattice-aligned period of wales near the middle, within the bands' run.
  if (W - R - L >= least_periods * P) {
    int w0 = repeat.wale0 + P * ((W / 2 - P / 2 - repeat.wale0) / P);
    w0 = std::clamp(w0, L, W - R - P);
    auto middle = [=](int w) { return w >= L && w < W - R; };
    if (B > 0) jobs.push_back({Block{0, B + context, w0, w0 + P, true}, [=](int c, int w) { return c < B && middle(w); }, {}, false});
    if (T > 0) jobs.push_back({Block{C - T - context, C, w0, w0 + P, true}, [=](int c, int w) { return c >= C - T && middle(w); }, {}, false});
  }
  // Up: a period of courses near the middle whose yarn turns inside the block (the
  // selvedge's runs go in and out of the held side), one parity or the other.
  if (C - T - B >= least_periods * Q + 1) {
    auto middle = [=](int c) { return c >= B && c < C - T; };
    for (const bool left : {true, false}) {
      if ((left ? L : R) == 0) continue;
      const int w0 = left ? 0 : W - R - context, w1 = left ? L + context : W;
      const int c0 = std::clamp(repeat.course0 + Q * ((C / 2 - repeat.course0) / Q), B, C - T - Q - 1);
      for (const int c : {c0, c0 + 1}) {
        Strip probe;
        const Block b{c, c + Q, w0, w1, false};
        if (!make_strip(f, b, period, start, probe)) continue;
        jobs.push_back({b, [=](int cc, int w) { return middle(cc) && (left ? w < L : w >= W - R); }, std::move(probe), true});
        break;
      }
    }
  }
  struct Done {
    Relaxed relaxed;
    bool refused = false;
  };
  std::vector<Done> done(jobs.size());
  parallel_for(jobs.size(), thread_count(options.threads), [&](std::size_t k) {
    Job& job = jobs[k];
    if (!job.made) job.made = make_strip(f, job.block, period, start, job.strip);
    if (!job.made) return;
    Done& d = done[k];
    d.refused = deeper_than_laid(job.strip.layout, job.strip.runs, sizes, job.strip.start, options.threads);
    if (!d.refused) d.relaxed = relax_chains(job.strip.layout, job.strip.runs, sizes, strip_options, &job.strip.start);
  });
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const Job& job = jobs[k];
    const Done& d = done[k];
    if (!job.made || d.refused) continue;  // a band whose strip started too deep is left to the edges' relaxation
    std::vector<int> targets;
    for (int c = 0; c < C; ++c)
      for (int w = 0; w < W; ++w)
        if (job.target(c, w)) targets.push_back(static_cast<int>(grid(c, w)));
    copy_strip(f, job.block, period, job.strip, d.relaxed.pieces, targets, start, out);
    ++out.relaxed;
    out.iterations = std::max(out.iterations, d.relaxed.stats.iterations);
    out.end_overlap = std::max(out.end_overlap, d.relaxed.stats.end_overlap);
  }
  return out;
}

}  // namespace knitc::relax
