#include "sweep_float_cache.h"

#include <fmt/format.h>

namespace rpu::app {

const image::Frame& FloatCache::get(const scene::CompiledScene& scene, const std::string& key,
                                    tracer::Method m, int n, int n1, int surf_n1_first) {
  const bool ideal = m == tracer::Method::kIdeal;
  const std::string k = fmt::format("{}|{}|{}|{}|{}", key, ideal, ideal ? 0 : n, ideal ? 0 : n1,
                                    ideal ? 0 : surf_n1_first);
  {
    std::lock_guard<std::mutex> lock(mu_);
    const auto it = frames_.find(k);
    if (it != frames_.end()) return *it->second;
  }
  tracer::FloatOptions fo;
  fo.method = m;
  fo.n = ideal ? 16 : n;
  fo.n1 = ideal ? 2 : n1;
  fo.surf_n1_first = ideal ? 0 : surf_n1_first;
  fo.threads = 1;
  auto frame = std::make_shared<const image::Frame>(tracer::render_float(scene, fo));
  std::lock_guard<std::mutex> lock(mu_);
  const auto [it, inserted] = frames_.emplace(k, std::move(frame));
  return *it->second;
}

}  // namespace rpu::app
