// The editing benchmark's operations, written once over a small adapter per library so that
// topomesh, OpenMesh and CGAL run the same policy (the same random choices, the same
// thresholds, the same queue). An adapter E (an object holding its mesh) gives, with
// integer ids (vertex, edge, half-edge, triangle):
//   n_edges(), n_triangles() (id bounds), live_triangles(), edge_removed(e),
//   edge_half_edge(e), edge_of(h), half_edge_removed(h), origin(h), target(h), apexes(h)
//   (the third vertex of the triangle of h and of the one across, ~0u where none), point(v),
//   set_point(v, p), flip_ok(e), flip(e), split(e, p), collapse_ok(h), collapse(h) (the
//   kept vertex), each_triangle_around(v, f(a, b, c)), each_out_half_edge(v, f(h)),
//   remove_triangle(t), garbage_collect(), structure_bytes().
// The shortest-edge simplification is the policy of `topomesh simplify` (cli/src/simplify.rs):
// one queue entry per edge keyed by its length's bits and a half-edge, stale entries
// re-queued, the link condition (the library's check) and no turned-over normal, the merged
// vertex at the midpoint.
#pragma once

#include "bench_util.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace diffmesh {

using P3 = std::array<double, 3>;

// What every library is asked to do, from the same numbers.
struct EditParams {
  uint64_t seed = 1;
  size_t flips = 1000000;        // flip storm attempts
  double split_factor = 1.5;     // split edges longer than this times the mean edge length
  double simplify_ratio = 0.1;   // keep this fraction of the triangles
};

// One timed operation on one library.
struct EditResult {
  double ms = -1;                // CPU time of the benchmark thread
  uint64_t attempts = 0, accepted = 0;
  size_t triangles_after = 0;    // live triangles
  size_t bytes_after = 0;        // the library's own structure size (positions excluded)
};

// The operations of one library on one mesh, and its memory.
struct EditRow {
  std::string lib;
  EditResult flips, splits, simplify, gc;
  double simplify_queue_ms = -1; // the simplification's queue operations replayed alone
  size_t simplify_queue_ops = 0;
  size_t bytes_built = 0;        // structure size right after the build
  long rss_build = -1;           // resident-set growth over the build
  long rss_edited = -1;          // ... over the build and the flip storm
};

inline double len2(const P3 &a, const P3 &b) {
  double s = 0;
  for (int k = 0; k < 3; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return s;
}
inline P3 midpoint(const P3 &a, const P3 &b) { return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}; }

// Mean length of the live edges.
template <class E> double mean_edge_length(E &ed) {
  double sum = 0;
  size_t n = 0;
  for (uint32_t e = 0; e < ed.n_edges(); ++e) {
    if (ed.edge_removed(e)) continue;
    uint32_t h = ed.edge_half_edge(e);
    sum += std::sqrt(len2(ed.point(ed.origin(h)), ed.point(ed.target(h))));
    ++n;
  }
  return n ? sum / double(n) : 0;
}

// Flip storm: `flips` times, a uniformly random edge id (the same seeded generator
// everywhere), flipped when the library's check allows it.
template <class E> EditResult flip_storm(E &ed, const EditParams &p) {
  EditResult r;
  std::mt19937_64 rng(p.seed);
  const uint64_t ne = ed.n_edges();
  double t0 = cpu_ms();
  for (size_t i = 0; i < p.flips; ++i) {
    uint32_t e = uint32_t(rng() % ne);
    ++r.attempts;
    if (ed.edge_removed(e) || !ed.flip_ok(e)) continue;
    ed.flip(e);
    ++r.accepted;
  }
  r.ms = cpu_ms() - t0;
  r.triangles_after = ed.live_triangles();
  r.bytes_after = ed.structure_bytes();
  return r;
}

// Is edge h (ends a, b) the longest edge of its triangles (ties allowed)?
template <class E> bool longest_of_its_triangles(E &ed, uint32_t h, const P3 &a, const P3 &b) {
  const double l = len2(a, b);
  uint32_t apex[2];
  ed.apexes(h, apex);
  for (uint32_t c : apex) {
    if (c == ~0u) continue;
    const P3 p = ed.point(c);
    if (len2(a, p) > l || len2(b, p) > l) return false;
  }
  return true;
}

// Edge-split refinement by longest-edge bisection: passes over the edge ids (new edges
// included as they come) split at its midpoint every edge longer than the threshold that is
// the longest of its triangles, until a pass splits none. (Splitting every long edge in id
// order regardless can run away on a real scan: a needle's short side, once split, leaves
// a new long median, and OpenMesh did not finish either; longest-edge bisection ends with
// every edge at most the threshold, since the longest edge of a triangle holding a longer
// one is longer still.)
template <class E> EditResult split_refine(E &ed, double threshold) {
  EditResult r;
  const double t2 = threshold * threshold;
  double t0 = cpu_ms();
  for (bool any = true; any;) {
    any = false;
    for (uint32_t e = 0; e < ed.n_edges(); ++e) {
      if (ed.edge_removed(e)) continue;
      ++r.attempts;
      uint32_t h = ed.edge_half_edge(e);
      P3 a = ed.point(ed.origin(h)), b = ed.point(ed.target(h));
      if (len2(a, b) <= t2 || !longest_of_its_triangles(ed, h, a, b)) continue;
      ed.split(e, midpoint(a, b));
      ++r.accepted;
      any = true;
    }
  }
  r.ms = cpu_ms() - t0;
  r.triangles_after = ed.live_triangles();
  r.bytes_after = ed.structure_bytes();
  return r;
}

// The key of a queued edge: its length's bits (non-negative doubles order as their bits) and
// the half-edge to collapse.
using EdgeKey = std::pair<uint64_t, uint32_t>;

// The queue operations of one simplification in order (a pop is e == ~0u), so that the
// queue's share of the run can be timed alone (replay_ms).
struct QueueOp {
  EdgeKey key;
  uint32_t e;
};
using QueueLog = std::vector<QueueOp>;

// A binary min-heap of edge ids whose keys can change in place (`slot[e]`: where edge e sits
// in `heap`, or none): cli/src/simplify.rs's EdgeQueue. With a log, it appends each operation.
class EdgeQueue {
public:
  explicit EdgeQueue(size_t edges, QueueLog *log = nullptr) : slot_(edges, kNone), log_(log) {
    heap_.reserve(edges);
  }
  void set(uint32_t e, EdgeKey key) {
    if (log_) log_->push_back({key, e});
    size_t i;
    if (slot_[e] == kNone) {
      heap_.push_back({key, e});
      i = heap_.size() - 1;
    } else {
      i = slot_[e];
      heap_[i].first = key;
    }
    down(up(i));
  }
  bool pop(EdgeKey &key, uint32_t &e) {
    if (log_) log_->push_back({{}, kNone});
    if (heap_.empty()) return false;
    std::swap(heap_[0], heap_.back());
    key = heap_.back().first;
    e = heap_.back().second;
    heap_.pop_back();
    slot_[e] = kNone;
    if (!heap_.empty()) down(0);
    return true;
  }

private:
  static constexpr uint32_t kNone = ~0u;
  using Item = std::pair<EdgeKey, uint32_t>;
  std::vector<Item> heap_;
  std::vector<uint32_t> slot_;
  QueueLog *log_;
  void place(size_t i, const Item &it) {
    slot_[it.second] = uint32_t(i);
    heap_[i] = it;
  }
  size_t up(size_t i) {
    Item it = heap_[i];
    while (i > 0 && it.first < heap_[(i - 1) / 2].first) {
      place(i, heap_[(i - 1) / 2]);
      i = (i - 1) / 2;
    }
    place(i, it);
    return i;
  }
  void down(size_t i) {
    Item it = heap_[i];
    const size_t n = heap_.size();
    for (;;) {
      size_t l = 2 * i + 1;
      if (l >= n) break;
      size_t c = l + 1 < n && heap_[l + 1].first < heap_[l].first ? l + 1 : l;
      if (!(heap_[c].first < it.first)) break;
      place(i, heap_[c]);
      i = c;
    }
    place(i, it);
  }
};

template <class E> uint64_t length_bits(E &ed, uint32_t h) {
  double l = std::sqrt(len2(ed.point(ed.origin(h)), ed.point(ed.target(h))));
  uint64_t b;
  std::memcpy(&b, &l, sizeof b);
  return b;
}

inline P3 cross(const P3 &u, const P3 &v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
inline P3 sub(const P3 &a, const P3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// Would moving both ends of h to `mid` turn the normal of a triangle around them over?
template <class E> bool flips_a_normal(E &ed, uint32_t h, const P3 &mid) {
  const uint32_t a = ed.origin(h), b = ed.target(h);
  bool flips = false;
  for (uint32_t x : {a, b})
    ed.each_triangle_around(x, [&](uint32_t c0, uint32_t c1, uint32_t c2) {
      const uint32_t c[3] = {c0, c1, c2};
      bool has_a = false, has_b = false;
      for (uint32_t y : c) has_a = has_a || y == a, has_b = has_b || y == b;
      if (flips || (has_a && has_b)) return;
      P3 p[3], q[3];
      for (int k = 0; k < 3; ++k) {
        p[k] = ed.point(c[k]);
        q[k] = c[k] == a || c[k] == b ? mid : p[k];
      }
      P3 n0 = cross(sub(p[1], p[0]), sub(p[2], p[0])), n1 = cross(sub(q[1], q[0]), sub(q[2], q[0]));
      if (n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2] <= 0) flips = true;
    });
  return flips;
}

// Shortest-edge-first collapses until at most ratio x the live triangles remain, or no
// edge can go. attempts: candidates checked; accepted: collapses. With `log`, the queue's
// operations are recorded (a run for replay_ms, not a timed one).
template <class E> EditResult simplify(E &ed, double ratio, QueueLog *log = nullptr) {
  EditResult r;
  const size_t target = size_t(double(ed.live_triangles()) * ratio);
  double t0 = cpu_ms();
  EdgeQueue queue(ed.n_edges(), log);
  for (uint32_t e = 0; e < ed.n_edges(); ++e) {
    if (ed.edge_removed(e)) continue;
    uint32_t h = ed.edge_half_edge(e);
    queue.set(e, {length_bits(ed, h), h});
  }
  EdgeKey key;
  uint32_t e;
  while (ed.live_triangles() > target && queue.pop(key, e)) {
    const uint32_t h = key.second;
    if (ed.edge_removed(e) || ed.half_edge_removed(h) || ed.edge_of(h) != e) continue;
    const uint64_t now = length_bits(ed, h);
    if (now != key.first) {
      queue.set(e, {now, h});
      continue;
    }
    ++r.attempts;
    const P3 mid = midpoint(ed.point(ed.origin(h)), ed.point(ed.target(h)));
    if (!ed.collapse_ok(h) || flips_a_normal(ed, h, mid)) continue;
    const uint32_t kept = ed.collapse(h);
    ed.set_point(kept, mid);
    ++r.accepted;
    ed.each_out_half_edge(kept, [&](uint32_t g) { queue.set(ed.edge_of(g), {length_bits(ed, g), g}); });
  }
  r.ms = cpu_ms() - t0;
  r.triangles_after = ed.live_triangles();
  r.bytes_after = ed.structure_bytes();
  return r;
}

// The CPU time of `log`'s operations on an empty queue for `edges` edges: the policy's own
// work in a simplification that made them, which every library pays alike (the part of its
// time no library can save).
inline double replay_ms(const QueueLog &log, size_t edges) {
  EdgeQueue queue(edges);
  EdgeKey key;
  uint32_t e;
  uint64_t sink = 0;
  double t0 = cpu_ms();
  for (const QueueOp &op : log) {
    if (op.e != ~0u) {
      queue.set(op.e, op.key);
    } else if (queue.pop(key, e)) {
      sink += e;
    }
  }
  double ms = cpu_ms() - t0;
  volatile uint64_t keep = sink;
  (void)keep;
  return ms;
}

// Removes every other triangle id (untimed), then times the garbage collection alone.
template <class E> EditResult remove_half_and_collect(E &ed) {
  EditResult r;
  for (uint32_t t = 0; t < ed.n_triangles(); t += 2) {
    ed.remove_triangle(t);
    ++r.attempts;
  }
  double t0 = cpu_ms();
  ed.garbage_collect();
  r.ms = cpu_ms() - t0;
  r.accepted = r.attempts;
  r.triangles_after = ed.live_triangles();
  r.bytes_after = ed.structure_bytes();
  return r;
}

// Every operation on fresh builds of one library: `make()` builds an adapter (untimed; it
// owns its mesh), each operation runs on its own build; the memory columns come from the
// flip storm's build. Repetitions keep the median time.
template <class Make> EditRow run_edits(const std::string &lib, Make make, const EditParams &p, double threshold,
                                        int reps) {
  EditRow row;
  row.lib = lib;
  auto median_of = [&](EditResult &out, auto op) {
    std::vector<double> ms;
    for (int i = 0; i < reps; ++i) {
      auto ed = make();
      out = op(*ed);
      ms.push_back(out.ms);
    }
    out.ms = median(ms);
  };
  {
    long before = rss_bytes();
    auto ed = make();
    row.rss_build = rss_bytes() - before;
    row.bytes_built = ed->structure_bytes();
    row.flips = flip_storm(*ed, p);
    row.rss_edited = rss_bytes() - before;
  }
  if (reps > 1) median_of(row.flips, [&](auto &ed) { return flip_storm(ed, p); });
  median_of(row.splits, [&](auto &ed) { return split_refine(ed, threshold); });
  median_of(row.simplify, [&](auto &ed) { return simplify(ed, p.simplify_ratio); });
  {
    // One more simplification records its queue operations, replayed alone `reps` times.
    QueueLog log;
    auto ed = make();
    const size_t edges = ed->n_edges();
    simplify(*ed, p.simplify_ratio, &log);
    std::vector<double> ms;
    for (int i = 0; i < reps; ++i) ms.push_back(replay_ms(log, edges));
    row.simplify_queue_ms = median(ms);
    row.simplify_queue_ops = log.size();
  }
  median_of(row.gc, [&](auto &ed) { return remove_half_and_collect(ed); });
  return row;
}

} // namespace diffmesh
