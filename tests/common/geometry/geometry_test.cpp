// clip_segment (Liang–Barsky, common/geometry/geometry.h): hand cases, then a randomized check
// against an exact parametric clip written here with rational arithmetic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <random>

#include "common/geometry/geometry.h"

namespace fleetmap {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(Point a, Point b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y); }

const Rect kBox{0, 0, 10, 10};

TEST(ClipSegment, FullyInsideIsUnchangedBitForBit) {
  const Point a{0.1, 0.7}, b{9.300000000000001, 3.3333333333333335};
  auto c = clip_segment(a, b, kBox);
  ASSERT_TRUE(c);
  EXPECT_TRUE(same_bits(c->a, a));
  EXPECT_TRUE(same_bits(c->b, b));
  // Ends on the rectangle's boundary are inside (closed rectangle) and also unchanged.
  auto e = clip_segment({0, 0.1}, {10, 9.9}, kBox);
  ASSERT_TRUE(e);
  EXPECT_TRUE(same_bits(e->a, {0, 0.1}));
  EXPECT_TRUE(same_bits(e->b, {10, 9.9}));
}

TEST(ClipSegment, CrossingOneEdge) {
  // Leaves through x = 10 at t = 0.8: (2,3) + 0.8 * (10,5) = (10,7).
  auto c = clip_segment({2, 3}, {12, 8}, kBox);
  ASSERT_TRUE(c);
  EXPECT_TRUE(same_bits(c->a, {2, 3}));
  EXPECT_DOUBLE_EQ(c->b.x, 10);
  EXPECT_DOUBLE_EQ(c->b.y, 7);
  // Entering through y = 0 at t = 1/4: (4,-2) + 0.25 * (4,8) = (5,0); orientation kept.
  auto d = clip_segment({4, -2}, {8, 6}, kBox);
  ASSERT_TRUE(d);
  EXPECT_DOUBLE_EQ(d->a.x, 5);
  EXPECT_DOUBLE_EQ(d->a.y, 0);
  EXPECT_TRUE(same_bits(d->b, {8, 6}));
  // Same segment reversed: the cut end is now b.
  auto r = clip_segment({8, 6}, {4, -2}, kBox);
  ASSERT_TRUE(r);
  EXPECT_TRUE(same_bits(r->a, {8, 6}));
  EXPECT_DOUBLE_EQ(r->b.x, 5);
  EXPECT_DOUBLE_EQ(r->b.y, 0);
}

TEST(ClipSegment, CrossingTwoEdges) {
  // Straight through, left to right.
  auto c = clip_segment({-5, 5}, {15, 5}, kBox);
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->a.x, 0);
  EXPECT_DOUBLE_EQ(c->a.y, 5);
  EXPECT_DOUBLE_EQ(c->b.x, 10);
  EXPECT_DOUBLE_EQ(c->b.y, 5);
  // Across a corner, the line x + y = 2: enters through x = 0 at (0,2), leaves through y = 0 at (2,0).
  auto k = clip_segment({-2, 4}, {4, -2}, kBox);
  ASSERT_TRUE(k);
  EXPECT_DOUBLE_EQ(k->a.x, 0);
  EXPECT_DOUBLE_EQ(k->a.y, 2);
  EXPECT_DOUBLE_EQ(k->b.x, 2);
  EXPECT_DOUBLE_EQ(k->b.y, 0);
  // Diagonal through two opposite corners: (-5,-5)-(15,15) -> (0,0)-(10,10).
  auto g = clip_segment({-5, -5}, {15, 15}, kBox);
  ASSERT_TRUE(g);
  EXPECT_DOUBLE_EQ(g->a.x, 0);
  EXPECT_DOUBLE_EQ(g->a.y, 0);
  EXPECT_DOUBLE_EQ(g->b.x, 10);
  EXPECT_DOUBLE_EQ(g->b.y, 10);
}

TEST(ClipSegment, TouchingACornerOnlyIsNothing) {
  // y = x + 10 passes the corner (0,10) and nothing else of the box.
  EXPECT_FALSE(clip_segment({-1, 9}, {1, 11}, kBox));
  EXPECT_FALSE(clip_segment({1, 11}, {-1, 9}, kBox));
  // Ending exactly at a corner from outside.
  EXPECT_FALSE(clip_segment({12, -2}, {10, 0}, kBox));
  // Touching an edge at one point from outside.
  EXPECT_FALSE(clip_segment({10, 5}, {15, 5}, kBox));
  EXPECT_FALSE(clip_segment({3, 14}, {5, 10}, kBox));
}

TEST(ClipSegment, LyingOnAnEdge) {
  // The rectangle is closed: a segment on its edge is in it.
  auto c = clip_segment({2, 0}, {8, 0}, kBox);
  ASSERT_TRUE(c);
  EXPECT_TRUE(same_bits(c->a, {2, 0}));
  EXPECT_TRUE(same_bits(c->b, {8, 0}));
  auto d = clip_segment({-3, 10}, {13, 10}, kBox);
  ASSERT_TRUE(d);
  EXPECT_DOUBLE_EQ(d->a.x, 0);
  EXPECT_DOUBLE_EQ(d->a.y, 10);
  EXPECT_DOUBLE_EQ(d->b.x, 10);
  EXPECT_DOUBLE_EQ(d->b.y, 10);
  auto e = clip_segment({10, 12}, {10, -1}, kBox);
  ASSERT_TRUE(e);
  EXPECT_DOUBLE_EQ(e->a.y, 10);
  EXPECT_DOUBLE_EQ(e->b.y, 0);
  EXPECT_DOUBLE_EQ(e->a.x, 10);
  EXPECT_DOUBLE_EQ(e->b.x, 10);
}

TEST(ClipSegment, ParallelOutside) {
  EXPECT_FALSE(clip_segment({-1, 2}, {-1, 8}, kBox));
  EXPECT_FALSE(clip_segment({11, -20}, {11, 20}, kBox));
  EXPECT_FALSE(clip_segment({2, 11}, {8, 11}, kBox));
  EXPECT_FALSE(clip_segment({-20, -0.5}, {20, -0.5}, kBox));
  // Collinear with an edge but beyond its end.
  EXPECT_FALSE(clip_segment({11, 0}, {15, 0}, kBox));
}

TEST(ClipSegment, EntirelyOutsideNotParallel) {
  EXPECT_FALSE(clip_segment({11, 11}, {15, 20}, kBox));
  EXPECT_FALSE(clip_segment({-5, 4}, {4, 20}, kBox));  // passes (0,12.9): above the box
}

TEST(ClipSegment, Degenerate) {
  // Zero-length segments: nothing, inside or outside.
  EXPECT_FALSE(clip_segment({5, 5}, {5, 5}, kBox));
  EXPECT_FALSE(clip_segment({0, 0}, {0, 0}, kBox));
  EXPECT_FALSE(clip_segment({20, 5}, {20, 5}, kBox));
  // A zero-width rectangle: a crossing segment meets it in one point only.
  EXPECT_FALSE(clip_segment({-1, 5}, {1, 5}, Rect{0, 0, 0, 10}));
  // A zero-area rectangle (a point).
  EXPECT_FALSE(clip_segment({-1, -1}, {1, 1}, Rect{0, 0, 0, 0}));
}

// A cut end lies on the rectangle's edge exactly, never one rounding step outside:
// windows are sent as seed text and their reader checks every end against the border
// (Rect::contains, exact).
TEST(ClipSegment, CutEndsAreInsideExactly) {
  // t1 = 7.9 / 8.9 from y = 10; a.y + t1 * d.y rounds to 10.000000000000002.
  auto c = clip_segment({-2.7, 2.1}, {10.8, 11.0}, kBox);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->a.x, 0);
  EXPECT_EQ(c->b.y, 10);
  EXPECT_TRUE(kBox.contains(c->a) && kBox.contains(c->b))
      << "(" << c->a.x << "," << c->a.y << ")-(" << c->b.x << "," << c->b.y << ")";
  // t0 = 0.6 / 0.7 from x = 0.1; a.x + t0 * d.x rounds to 0.09999999999999998.
  const Rect r{0.1, 0.1, 0.7, 0.3};
  auto d = clip_segment({-0.5, -0.5}, {0.2, 0.2}, r);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->a.x, 0.1);
  EXPECT_EQ(d->a.y, 0.1);
  EXPECT_TRUE(r.contains(d->a) && r.contains(d->b)) << "(" << d->a.x << "," << d->a.y << ")";
}

TEST(ClipSegment, RandomCutEndsAreInsideExactly) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-30, 30);
  int outside = 0, clipped = 0;
  for (int iter = 0; iter < 100000; ++iter) {
    double x0 = u(rng), x1 = u(rng), y0 = u(rng), y1 = u(rng);
    const Rect r{std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1)};
    if (auto c = clip_segment({u(rng), u(rng)}, {u(rng), u(rng)}, r)) {
      ++clipped;
      if (!r.contains(c->a) || !r.contains(c->b)) ++outside;
    }
  }
  EXPECT_GT(clipped, 10000);
  EXPECT_EQ(outside, 0) << "of " << clipped << " clipped segments";
}

// ---- randomized: exact rational clipping ------------------------------------------

struct Frac {  // n / d with d > 0
  int64_t n, d;
};
bool less(Frac a, Frac b) { return a.n * b.d < b.n * a.d; }
Frac frac(int64_t n, int64_t d) { return d < 0 ? Frac{-n, -d} : Frac{n, d}; }

// The parameter interval [lo, hi] of the part of ab in r, exactly; nullopt when empty.
std::optional<std::pair<Frac, Frac>> exact_interval(const int64_t a[2], const int64_t b[2], const int64_t lo_r[2],
                                                    const int64_t hi_r[2]) {
  Frac lo{0, 1}, hi{1, 1};
  for (int k = 0; k < 2; ++k) {
    const int64_t d = b[k] - a[k];
    if (d == 0) {
      if (a[k] < lo_r[k] || a[k] > hi_r[k]) return std::nullopt;
      continue;
    }
    Frac t1 = frac(lo_r[k] - a[k], d), t2 = frac(hi_r[k] - a[k], d);
    if (less(t2, t1)) std::swap(t1, t2);
    if (less(lo, t1)) lo = t1;
    if (less(t2, hi)) hi = t2;
  }
  if (!less(lo, hi)) return std::nullopt;
  return std::pair{lo, hi};
}

TEST(ClipSegment, RandomAgainstExactRationalClip) {
  std::mt19937_64 rng(20240601);
  std::uniform_int_distribution<int64_t> coord(-12, 12);
  int kept = 0, dropped = 0, unclipped = 0;
  for (int iter = 0; iter < 200000; ++iter) {
    int64_t a[2] = {coord(rng), coord(rng)}, b[2] = {coord(rng), coord(rng)};
    int64_t lo[2] = {coord(rng), coord(rng)}, hi[2] = {coord(rng), coord(rng)};
    for (int k = 0; k < 2; ++k)
      if (lo[k] > hi[k]) std::swap(lo[k], hi[k]);
    const Rect r{double(lo[0]), double(lo[1]), double(hi[0]), double(hi[1])};
    const Point pa{double(a[0]), double(a[1])}, pb{double(b[0]), double(b[1])};
    const auto got = clip_segment(pa, pb, r);
    auto want = exact_interval(a, b, lo, hi);
    if (a[0] == b[0] && a[1] == b[1]) want.reset();  // zero length: nothing
    ASSERT_EQ(got.has_value(), want.has_value())
        << "a=(" << a[0] << "," << a[1] << ") b=(" << b[0] << "," << b[1] << ") r=[" << lo[0] << "," << lo[1]
        << "," << hi[0] << "," << hi[1] << "]";
    if (!got) {
      ++dropped;
      continue;
    }
    ++kept;
    const auto [t0, t1] = *want;
    const Point d = pb - pa;
    auto at = [&](Frac t) { return Point{pa.x + double(t.n) / double(t.d) * d.x, pa.y + double(t.n) / double(t.d) * d.y}; };
    if (t0.n == 0) { EXPECT_TRUE(same_bits(got->a, pa)); }
    if (t1.n == t1.d) { EXPECT_TRUE(same_bits(got->b, pb)); }
    if (t0.n == 0 && t1.n == t1.d) ++unclipped;
    const Point ea = at(t0), eb = at(t1);
    EXPECT_NEAR(got->a.x, ea.x, 1e-12);
    EXPECT_NEAR(got->a.y, ea.y, 1e-12);
    EXPECT_NEAR(got->b.x, eb.x, 1e-12);
    EXPECT_NEAR(got->b.y, eb.y, 1e-12);
  }
  // The generator must exercise every outcome.
  EXPECT_GT(kept, 10000);
  EXPECT_GT(dropped, 10000);
  EXPECT_GT(unclipped, 1000);
}

// Non-integer inputs: the clipped part contains every sample of ab that is clearly inside
// r, no sample that is clearly outside, and its ends are the original ends or lie on r's edge.
TEST(ClipSegment, RandomAgainstSampling) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-30, 30);
  for (int iter = 0; iter < 20000; ++iter) {
    const Point a{u(rng), u(rng)}, b{u(rng), u(rng)};
    double x0 = u(rng), x1 = u(rng), y0 = u(rng), y1 = u(rng);
    const Rect r{std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1)};
    const auto got = clip_segment(a, b, r);
    const Point d = b - a;
    const double len2 = dot(d, d);
    constexpr double kEps = 1e-9;
    auto inside = [&](Point p, double m) {
      return p.x > r.xmin + m && p.x < r.xmax - m && p.y > r.ymin + m && p.y < r.ymax - m;
    };
    auto param = [&](Point p) { return dot(p - a, d) / len2; };
    double t0 = 2, t1 = -1;
    if (got) {
      t0 = param(got->a);
      t1 = param(got->b);
      EXPECT_LT(t0, t1);
      EXPECT_NEAR(cross(d, got->a - a) / std::sqrt(len2), 0, 1e-9);
      EXPECT_NEAR(cross(d, got->b - a) / std::sqrt(len2), 0, 1e-9);
      for (Point p : {got->a, got->b}) {
        EXPECT_TRUE(inside(p, -kEps));
        const bool on_edge = std::abs(p.x - r.xmin) < kEps || std::abs(p.x - r.xmax) < kEps ||
                             std::abs(p.y - r.ymin) < kEps || std::abs(p.y - r.ymax) < kEps;
        EXPECT_TRUE(on_edge || same_bits(p, a) || same_bits(p, b));
      }
    }
    for (int k = 0; k <= 200; ++k) {
      const double t = k / 200.0;
      const Point p = a + t * d;
      if (inside(p, 1e-7)) {
        ASSERT_TRUE(got) << "sample inside the rectangle but nothing clipped, iter " << iter;
        EXPECT_GE(t, t0 - 1e-9);
        EXPECT_LE(t, t1 + 1e-9);
      } else if (!inside(p, -1e-7) && got) {
        EXPECT_TRUE(t < t0 + 1e-9 || t > t1 - 1e-9) << "sample outside the rectangle kept, iter " << iter;
      }
    }
  }
}

}  // namespace
}  // namespace fleetmap
