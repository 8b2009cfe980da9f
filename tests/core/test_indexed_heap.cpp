// The indexed heap of the fold measure's orientation walk: a best-first walk over random
// graphs pops the same (weight, id, payload) sequence as a heap of every offer with the stale
// ones skipped, ties in the weight included (weights drawn from a few values), and a later,
// heavier offer never replaces a lighter one.
#include <cstdint>
#include <functional>
#include <queue>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "indexed_heap.hpp"

// cmocka last, with C linkage (its header does not declare it).
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using namespace dbs;

namespace {

using Popped = std::tuple<double, std::uint32_t, std::uint32_t>;  // weight, id, payload

/// A random graph: each of n vertices joined to `degree` others (both directions), edge
/// weights from `levels` distinct values, so that many tie.
struct Graph {
  std::vector<std::vector<std::pair<std::uint32_t, double>>> edges;
};

Graph random_graph(std::uint32_t n, int degree, int levels, std::mt19937& rng) {
  Graph g;
  g.edges.resize(n);
  std::uniform_int_distribution<std::uint32_t> vertex(0, n - 1);
  std::uniform_int_distribution<int> level(0, levels - 1);
  for (std::uint32_t i = 0; i < n; ++i)
    for (int k = 0; k < degree; ++k) {
      const std::uint32_t j = vertex(rng);
      if (j == i) continue;
      const double w = 0.25 * level(rng);
      g.edges[i].push_back({j, w});
      g.edges[j].push_back({i, w});
    }
  return g;
}

/// The walk with a heap of every offer (the reference).
std::vector<Popped> walk_lazily(const Graph& g) {
  const std::size_t n = g.edges.size();
  std::vector<char> done(n, 0);
  std::vector<Popped> order;
  std::priority_queue<Popped, std::vector<Popped>, std::greater<Popped>> heap;
  for (std::uint32_t s = 0; s < n; ++s) {
    if (done[s]) continue;
    done[s] = 1;
    order.emplace_back(-1.0, s, s);
    for (const auto& [to, w] : g.edges[s])
      if (!done[to]) heap.emplace(w, to, s);
    while (!heap.empty()) {
      const Popped top = heap.top();
      heap.pop();
      const std::uint32_t to = std::get<1>(top);
      if (done[to]) continue;
      done[to] = 1;
      order.push_back(top);
      for (const auto& [next, w] : g.edges[to])
        if (!done[next]) heap.emplace(w, next, to);
    }
  }
  return order;
}

/// The same walk with the indexed heap.
std::vector<Popped> walk_indexed(const Graph& g) {
  const std::size_t n = g.edges.size();
  std::vector<char> done(n, 0);
  std::vector<Popped> order;
  IndexedMinHeap heap(n);
  for (std::uint32_t s = 0; s < n; ++s) {
    if (done[s]) continue;
    done[s] = 1;
    order.emplace_back(-1.0, s, s);
    for (const auto& [to, w] : g.edges[s])
      if (!done[to]) heap.offer(to, w, s);
    while (!heap.empty()) {
      const IndexedMinHeap::Entry top = heap.pop();
      assert_false(done[top.id]);
      done[top.id] = 1;
      order.emplace_back(top.weight, top.id, top.payload);
      for (const auto& [next, w] : g.edges[top.id])
        if (!done[next]) heap.offer(next, w, top.id);
    }
  }
  return order;
}

void walks_match_a_heap_of_every_offer(void**) {
  std::mt19937 rng(20261207);
  int compared = 0;
  for (std::uint32_t n : {1u, 2u, 7u, 100u, 2000u})
    for (int degree : {0, 1, 3, 10})
      for (int levels : {1, 3, 1000}) {
        const Graph g = random_graph(n, degree, levels, rng);
        const std::vector<Popped> lazy = walk_lazily(g), indexed = walk_indexed(g);
        assert_int_equal(indexed.size(), n);
        assert_int_equal(lazy.size(), indexed.size());
        for (std::size_t k = 0; k < lazy.size(); ++k) {
          assert_true(std::get<0>(lazy[k]) == std::get<0>(indexed[k]));
          assert_int_equal(std::get<1>(lazy[k]), std::get<1>(indexed[k]));
          assert_int_equal(std::get<2>(lazy[k]), std::get<2>(indexed[k]));
        }
        ++compared;
      }
  assert_int_equal(compared, 60);
}

void keeps_the_least_offer_of_an_id(void**) {
  IndexedMinHeap heap(4);
  heap.offer(2, 0.5, 9);
  heap.offer(2, 0.7, 1);  // heavier: ignored
  heap.offer(2, 0.5, 3);  // as light, lower payload: taken
  heap.offer(1, 0.5, 0);  // ties with 2 on the weight: the lower id first
  heap.offer(3, 0.1, 5);
  heap.offer(3, 0.2, 0);  // heavier: ignored
  IndexedMinHeap::Entry e = heap.pop();
  assert_int_equal(e.id, 3);
  assert_int_equal(e.payload, 5);
  assert_true(e.weight == 0.1);
  e = heap.pop();
  assert_int_equal(e.id, 1);
  e = heap.pop();
  assert_int_equal(e.id, 2);
  assert_int_equal(e.payload, 3);
  assert_true(e.weight == 0.5);
  assert_true(heap.empty());
  // An emptied heap serves another walk: an id popped in the first is offered anew and comes back.
  heap.offer(3, 2.0, 0);
  assert_false(heap.empty());
  assert_int_equal(heap.pop().id, 3);
  assert_true(heap.empty());
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(walks_match_a_heap_of_every_offer),
      cmocka_unit_test(keeps_the_least_offer_of_an_id),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
