// The float renders of a sweep, shared between its configurations: `float` depends on no
// hardware parameter and `float-ip` only on (n, n1, surf_n1_first), so each is rendered once per scene and
// resolution however many configurations compare against it.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "image/frame.h"
#include "scene/compiled_scene.h"
#include "tracer/float_tracer.h"

namespace rpu::app {

class FloatCache {
 public:
  // The frame of `scene` (known to the cache as `key`: the scene and its resolution) rendered
  // with method m, at (n, n1, surf_n1_first) for the iterative process. Thread-safe; two threads asking for a
  // frame not yet there may both render it, and the first stored is kept.
  const image::Frame& get(const scene::CompiledScene& scene, const std::string& key,
                          tracer::Method m, int n, int n1, int surf_n1_first);

 private:
  std::mutex mu_;
  std::map<std::string, std::shared_ptr<const image::Frame>> frames_;
};

}  // namespace rpu::app
