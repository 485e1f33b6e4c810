// A head's pipeline run over many samples, on several threads (the multiprecision reference
// costs microseconds to milliseconds per sample).
#pragma once

#include <atomic>
#include <thread>
#include <vector>

#include "accuracy/head_outcome.hpp"

namespace conescan::accuracy {

/// run(sample) for every sample: `run` is any callable from head_sample<T> to head_outcome<T>.
template <class T, class Run>
std::vector<head_outcome<T>> outcomes_of(const Run& run, const std::vector<head_sample<T>>& samples,
                                         unsigned threads = 1) {
  std::vector<head_outcome<T>> out(samples.size(), head_outcome<T>::failed(status::invalid));
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    // Small chunks: scenes differ a hundredfold in cost (misses search the whole scan circle).
    constexpr std::size_t chunk = 16;
    for (std::size_t begin = next.fetch_add(chunk); begin < samples.size();
         begin = next.fetch_add(chunk))
      for (std::size_t i = begin; i < begin + chunk && i < samples.size(); ++i)
        out[i] = run(samples[i]);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  return out;
}

template <class T>
std::vector<head_sample<T>> samples_of(const std::vector<scene_point>& scenes,
                                       const earth_figure& earth) {
  std::vector<head_sample<T>> out;
  out.reserve(scenes.size());
  for (const scene_point& s : scenes) out.push_back(make_head_sample<T>(s, earth));
  return out;
}

}  // namespace conescan::accuracy
