#include "client/localization/global_search.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>

#include "client/localization/free_space.h"
#include "client/localization/parallel.h"

namespace fleetmap::localization {

namespace {

constexpr float kNone = -std::numeric_limits<float>::infinity();

// Sliding maximum over [i, i + w) along one line of n values, step apart (clipped at the end).
void running_max(const float* in, float* out, int n, size_t step, int w) {
  for (int i = 0; i < n; ++i) {
    float m = kNone;
    for (int k = i; k < std::min(n, i + w); ++k) m = std::max(m, in[k * step]);
    out[i * step] = m;
  }
}

struct Scored {
  float score;
  Candidate candidate;
  bool operator>(const Scored& o) const { return score > o.score; }
};

}  // namespace

GlobalSearch::GlobalSearch(const Map& map, GlobalSearchOptions o) : options_(o), field_(map, o.field) {
  options_.block = std::max(1, o.block);
  const int w = field_.width(), h = field_.height(), b = options_.block;
  const size_t n = static_cast<size_t>(w) * h;
  const std::vector<float>& d = field_.distances();
  score_.resize(n);
  const double inv_two_var = 1 / (2 * o.sigma * o.sigma);
  for (size_t i = 0; i < n; ++i)
    score_[i] = static_cast<float>(std::max(-d[i] * d[i] * inv_two_var, -o.max_penalty));

  // Upper bounds for blocks: the max over the block's extent, rows then columns.
  std::vector<float> rows(n);
  for (int iy = 0; iy < h; ++iy) running_max(&score_[field_.index(0, iy)], &rows[field_.index(0, iy)], w, 1, b);
  pooled_.resize(n);
  for (int ix = 0; ix < w; ++ix) running_max(&rows[ix], &pooled_[ix], h, static_cast<size_t>(w), b);

  // Candidate cells: centre inside the border and free space, clear of the walls.
  const FreeSpace free_space(map);
  const Rect r = map.border.rect();
  allowed_.assign(n, 0);
  const int ix0 = std::max(0, field_.cell_x(r.xmin)), ix1 = std::min(w - 1, field_.cell_x(r.xmax));
  const int iy0 = std::max(0, field_.cell_y(r.ymin)), iy1 = std::min(h - 1, field_.cell_y(r.ymax));
  for (int iy = iy0; iy <= iy1; ++iy)
    for (int ix = ix0; ix <= ix1; ++ix) {
      const size_t i = field_.index(ix, iy);
      const Point c = field_.centre(ix, iy);
      allowed_[i] = d[i] >= o.clearance && r.contains(c) && free_space.contains(c);
    }
  bx0_ = ix0 / b;
  by0_ = iy0 / b;
  bx1_ = ix1 / b + 1;
  by1_ = iy1 / b + 1;
  options_.coarse = std::max(1, o.coarse);
  // The coarse level's bounds: the block bounds pooled over coarse blocks each way.
  const int c = options_.coarse;
  if (c > 1) {
    const auto pool = [&](const std::vector<float>& in, std::vector<float>& out, size_t step, int along, int n_lines,
                          size_t line_step) {
      for (int line = 0; line < n_lines; ++line)
        for (int i = 0; i < along; ++i) {
          float m = kNone;
          for (int k = 0; k < c && i + k * b < along; ++k) m = std::max(m, in[line * line_step + (i + k * b) * step]);
          out[line * line_step + i * step] = m;
        }
    };
    std::vector<float> tmp(n);
    pool(pooled_, tmp, 1, w, h, static_cast<size_t>(w));
    pooled_coarse_.resize(n);
    pool(tmp, pooled_coarse_, static_cast<size_t>(w), h, w, 1);
  }
  block_allowed_.assign(static_cast<size_t>(bx1_ - bx0_) * (by1_ - by0_), 0);
  for (int iy = iy0; iy <= iy1; ++iy)
    for (int ix = ix0; ix <= ix1; ++ix)
      if (allowed_[field_.index(ix, iy)])
        block_allowed_[static_cast<size_t>(iy / b - by0_) * (bx1_ - bx0_) + (ix / b - bx0_)] = 1;
}

double GlobalSearch::score(const Pose& pose, const std::vector<double>& ranges, const std::vector<double>& beams,
                           double rmax) const {
  const double res = field_.resolution();
  const int cx = field_.cell_x(pose.x), cy = field_.cell_y(pose.y);
  double s = 0;
  for (size_t j = 0; j < ranges.size(); ++j) {
    if (!(ranges[j] < rmax)) continue;
    const double a = pose.theta + beams[j];
    const int ix = std::clamp(cx + static_cast<int>(std::lround(ranges[j] * std::cos(a) / res)), 0, field_.width() - 1);
    const int iy = std::clamp(cy + static_cast<int>(std::lround(ranges[j] * std::sin(a) / res)), 0, field_.height() - 1);
    s += score_[field_.index(ix, iy)];
  }
  return s;
}

std::vector<Candidate> GlobalSearch::search(const std::vector<double>& ranges, const std::vector<double>& beams,
                                            double rmax, double heading, double half_width, size_t k) const {
  expanded_ = 0;
  const double res = field_.resolution();
  const int w = field_.width(), b = options_.block;
  // End points stay on the grid from any candidate cell (the margin is RMAX); farther
  // points (of stitched scans) are left out.
  const double reach = options_.field.margin - 2 * res;
  // Headings evenly spread over the compass's interval, at most heading_step apart.
  const int nh = half_width > 0 ? 2 * static_cast<int>(std::ceil(half_width / options_.heading_step)) + 1 : 1;
  std::vector<double> headings(nh);
  for (int k = 0; k < nh; ++k)
    headings[k] = normalize_angle(heading + (nh > 1 ? -half_width + 2 * half_width * k / (nh - 1) : 0.0));
  // Per heading, each hitting beam's end point as an offset in cells.
  std::vector<std::vector<ptrdiff_t>> offsets(nh);
  for (int k = 0; k < nh; ++k)
    for (size_t j = 0; j < ranges.size(); ++j) {
      if (!(ranges[j] < rmax) || !(ranges[j] >= 0) || ranges[j] > reach) continue;
      const double r = ranges[j], a = headings[k] + beams[j];
      offsets[k].push_back(std::lround(r * std::cos(a) / res) + static_cast<ptrdiff_t>(w) * std::lround(r * std::sin(a) / res));
    }
  if (offsets[0].empty()) return {};
  const auto sum = [](const std::vector<float>& table, size_t base, const std::vector<ptrdiff_t>& off) {
    float s = 0;
    for (ptrdiff_t o : off) s += table[base + o];
    return s;
  };

  // Block bounds (per heading) are computed when their coarse block is expanded.
  const int nbx = bx1_ - bx0_, nby = by1_ - by0_, c = options_.coarse;
  const size_t blocks = static_cast<size_t>(nbx) * nby;
  std::vector<float> bound(blocks * nh, kNone);
  const auto bound_block = [&](size_t blk) {
    const size_t base = field_.index((bx0_ + static_cast<int>(blk % nbx)) * b, (by0_ + static_cast<int>(blk / nbx)) * b);
    float best = kNone;
    for (int k = 0; k < nh; ++k) best = std::max(best, bound[blk * nh + k] = sum(pooled_, base, offsets[k]));
    return best;
  };
  // Entries to expand: coarse blocks (ids from `blocks` on) and blocks, best bound first.
  struct Entry {
    float bound;
    uint32_t id;
    bool operator<(const Entry& o) const { return bound < o.bound || (bound == o.bound && id > o.id); }
  };
  std::vector<Entry> initial;
  if (c > 1) {
    const int ncx = (nbx + c - 1) / c, ncy = (nby + c - 1) / c;
    std::vector<Entry> coarse(static_cast<size_t>(ncx) * ncy, Entry{kNone, 0});
    parallel_for(options_.threads, static_cast<size_t>(ncy), [&](int, size_t row0, size_t row1) {
      for (size_t row = row0; row < row1; ++row)
        for (int col = 0; col < ncx; ++col) {
          bool any = false;
          for (int r = static_cast<int>(row) * c; r < std::min(nby, (static_cast<int>(row) + 1) * c) && !any; ++r)
            for (int q = col * c; q < std::min(nbx, (col + 1) * c) && !any; ++q) any = block_allowed_[static_cast<size_t>(r) * nbx + q];
          if (!any) continue;
          const size_t base = field_.index((bx0_ + col * c) * b, (by0_ + static_cast<int>(row) * c) * b);
          float best = kNone;
          for (int k = 0; k < nh; ++k) best = std::max(best, sum(pooled_coarse_, base, offsets[k]));
          coarse[row * ncx + col] = {best, static_cast<uint32_t>(blocks + row * ncx + col)};
        }
    });
    for (const Entry& e : coarse)
      if (e.bound > kNone) initial.push_back(e);
  } else {
    std::vector<Entry> all(blocks, Entry{kNone, 0});
    parallel_for(options_.threads, blocks, [&](int, size_t b0, size_t b1) {
      for (size_t blk = b0; blk < b1; ++blk)
        if (block_allowed_[blk]) all[blk] = {bound_block(blk), static_cast<uint32_t>(blk)};
    });
    for (const Entry& e : all)
      if (e.bound > kNone) initial.push_back(e);
  }
  std::priority_queue<Entry> open(std::less<Entry>(), std::move(initial));
  const int ncx = (nbx + c - 1) / c;

  // Expand best bound first, a batch per thread pass; keep the K best blocks.
  const size_t k_best = std::max<size_t>(1, k);
  std::priority_queue<Scored, std::vector<Scored>, std::greater<Scored>> top;  // the worst of the K on top
  const auto threshold = [&] { return top.size() < k_best ? kNone : top.top().score; };
  const size_t batch = 16 * static_cast<size_t>(std::max(1, options_.threads));
  std::vector<Entry> taken;
  std::vector<Scored> found(batch);
  std::vector<std::vector<Entry>> children(batch);
  while (!open.empty() && open.top().bound > threshold()) {
    const float cut = threshold();
    taken.clear();
    while (taken.size() < batch && !open.empty() && open.top().bound > cut) {
      taken.push_back(open.top());
      open.pop();
    }
    parallel_for(options_.threads, taken.size(), [&](int, size_t i0, size_t i1) {
      for (size_t i = i0; i < i1; ++i) {
        found[i] = {kNone, {}};
        children[i].clear();
        if (taken[i].id >= blocks) {  // a coarse block: bound its blocks
          const size_t cb = taken[i].id - blocks;
          const int col = static_cast<int>(cb % ncx), row = static_cast<int>(cb / ncx);
          for (int r = row * c; r < std::min(nby, (row + 1) * c); ++r)
            for (int q = col * c; q < std::min(nbx, (col + 1) * c); ++q) {
              const size_t blk = static_cast<size_t>(r) * nbx + q;
              if (!block_allowed_[blk]) continue;
              const float bb = bound_block(blk);
              if (bb > cut) children[i].push_back({bb, static_cast<uint32_t>(blk)});
            }
          continue;
        }
        const uint32_t blk = taken[i].id;
        const int bx = bx0_ + static_cast<int>(blk % nbx), by = by0_ + static_cast<int>(blk / nbx);
        Scored best{kNone, {}};
        for (int k = 0; k < nh; ++k) {
          if (!(bound[static_cast<size_t>(blk) * nh + k] > std::max(cut, best.score))) continue;
          for (int iy = by * b; iy < std::min(field_.height(), (by + 1) * b); ++iy)
            for (int ix = bx * b; ix < std::min(w, (bx + 1) * b); ++ix) {
              const size_t cell = field_.index(ix, iy);
              if (!allowed_[cell]) continue;
              const float s = sum(score_, cell, offsets[k]);
              if (s > best.score) {
                const Point p = field_.centre(ix, iy);
                best = {s, {{p.x, p.y, headings[k]}, s}};
              }
            }
        }
        found[i] = best;
      }
    });
    for (size_t i = 0; i < taken.size(); ++i) {
      for (const Entry& e : children[i]) open.push(e);
      if (taken[i].id >= blocks) continue;
      ++expanded_;
      if (found[i].score == kNone) continue;
      if (top.size() < k_best) top.push(found[i]);
      else if (found[i].score > top.top().score) {
        top.pop();
        top.push(found[i]);
      }
    }
  }
  std::vector<Candidate> out;
  for (; !top.empty(); top.pop()) out.push_back(top.top().candidate);
  std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace fleetmap::localization
