// Shared pieces of the benchmarks: the splitmix64 generator of docs/performance.md, aligned
// pre-faulted buffers, and the W1 and W2 input sets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <vector>

#include "casteljau/core/point.hpp"

namespace bench {

/// splitmix64 exactly as docs/performance.md ("Workloads") states it. The workload definitions
/// ask for "a fixed seed for each workload" without giving it; we use the workload
/// number (W1: 1, W2: 2), so a peer reproduces the inputs from this comment alone.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// In [0, 1): the top 53 bits times 2^-53 (exact).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }

 private:
  std::uint64_t state_;
};

inline constexpr std::uint64_t w1_seed = 1;
inline constexpr std::uint64_t w2_seed = 2;

/// A 2 MiB-aligned (so transparent huge pages can back it), pre-faulted array: every
/// page is written once here so that first-touch page faults are never timed.
template <class T>
class Buffer {
 public:
  explicit Buffer(std::size_t n) : n_(n) {
    const std::size_t align = std::size_t{2} << 20;
    const std::size_t bytes = ((n * sizeof(T) + align - 1) / align) * align;
    p_ = static_cast<T*>(std::aligned_alloc(align, bytes));
    if (!p_) throw std::bad_alloc();
    std::memset(static_cast<void*>(p_), 0, bytes);
  }
  ~Buffer() { std::free(p_); }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  T* data() { return p_; }
  const T* data() const { return p_; }
  std::size_t size() const { return n_; }
  T& operator[](std::size_t i) { return p_[i]; }
  const T& operator[](std::size_t i) const { return p_[i]; }

 private:
  T* p_;
  std::size_t n_;
};

/// W1: 1000 cubics, P_k.x then P_k.y for k = 0..3, curve by curve; t_j = j / 9999.
struct W1Data {
  static constexpr std::size_t curves = 1000;
  static constexpr std::size_t params = 10000;
  static constexpr std::size_t points = curves * params;
  std::vector<std::array<casteljau::Point<double, 2>, 4>> P;  // P[i][k]
  std::vector<double> ts;

  W1Data() : P(curves), ts(params) {
    SplitMix64 rng(w1_seed);
    for (auto& c : P)
      for (auto& p : c) {
        p[0] = rng.uniform();
        p[1] = rng.uniform();
      }
    for (std::size_t j = 0; j < params; ++j) ts[j] = static_cast<double>(j) / 9999.0;
  }
};

/// W2: for n in (5, 10, 20, 40): 10 curves of n + 1 points (x then y), then 1000
/// parameters t = uniform(), all from one generator in that order.
struct W2Set {
  int n;
  std::vector<std::vector<casteljau::Point<double, 2>>> P;  // 10 curves
  std::vector<double> ts;                                   // 1000 parameters
};

inline std::vector<W2Set> w2_data() {
  SplitMix64 rng(w2_seed);
  std::vector<W2Set> sets;
  for (int n : {5, 10, 20, 40}) {
    W2Set s{n, {}, {}};
    for (int c = 0; c < 10; ++c) {
      std::vector<casteljau::Point<double, 2>> P(static_cast<std::size_t>(n) + 1);
      for (auto& p : P) {
        p[0] = rng.uniform();
        p[1] = rng.uniform();
      }
      s.P.push_back(std::move(P));
    }
    for (int j = 0; j < 1000; ++j) s.ts.push_back(rng.uniform());
    sets.push_back(std::move(s));
  }
  return sets;
}

}  // namespace bench
