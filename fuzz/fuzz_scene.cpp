// fuzz_scene (issue 14, item 3): bytes → scene file text → the scene reader (parse_scene) → the
// scene compiler (compile_scene: normals, segment constants, camera, bins, classification grid,
// surfaces) → the model's compiler (quantize_scene at the default hardware parameters, when the
// scene has no patches) and every patch prepared and evaluated at a few parameters.
//
// A bad scene must be refused with one rpu::Error: one line, naming the file. Any other
// exception (libFuzzer reports it as a crash), a crash, a hang, undefined behaviour or a leak is
// a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "common/error.h"
#include "model/descriptors.h"
#include "model/hw_params.h"
#include "patch/patch_surface.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"

namespace {

constexpr const char* kSource = "fuzz.json";

// A user-facing error is one non-empty line naming the file.
void check_message(const rpu::Error& e) {
  const std::string what = e.what();
  if (what.empty() || what.find('\n') != std::string::npos || what.find(kSource) == std::string::npos ||
      e.problem().empty()) {
    std::fprintf(stderr, "fuzz_scene: malformed error message: [%s]\n", what.c_str());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const rpu::scene::Scene scene = rpu::scene::parse_scene(text, kSource);
    const rpu::scene::CompiledScene sc = rpu::scene::compile_scene(scene);
    for (const rpu::scene::Patch& p : sc.patches) {
      const rpu::patch::PatchSurface s(p);
      for (const double u : {0.0, 0.37, 1.0})
        for (const double v : {0.0, 0.61, 1.0}) (void)s.evaluate(u, v);
    }
    if (sc.patches.empty()) (void)rpu::ref::quantize_scene(sc, rpu::ref::HwParams{});
  } catch (const rpu::Error& e) {
    check_message(e);
  }
  return 0;
}
