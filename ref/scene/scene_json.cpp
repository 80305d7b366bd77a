#include "scene/scene_json.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/json_input.h"
#include "common/input_file.h"
#include "common/limits.h"
#include "scene/scene_keys.h"

namespace rpu::scene {
namespace {

using Json = nlohmann::json;

// A location in the scene file: the source name and a JSON path ("" is the top level).
struct Where {
  const std::string& source;
  std::string path;

  Where key(std::string_view k) const {
    return {source, path.empty() ? std::string(k) : path + "." + std::string(k)};
  }
  Where index(size_t i) const { return {source, path + "[" + std::to_string(i) + "]"}; }
  [[noreturn]] void fail(const std::string& problem) const {
    throw Error(path.empty() ? source : source + ": " + path, problem);
  }
};

Json parse_json(const std::string& text, const std::string& source) {
  return json_input::parse(text, source,
                           "the file is empty; expected a JSON object with a 'camera' key");
}

using json_input::describe;

// The keys accepted at an object path of scene_keys.h; an unknown path does not compile.
consteval std::span<const std::string_view> keys_of(std::string_view path) {
  return accepted_keys(path);
}

// Checks that `j` is an object whose keys are all in `allowed` (keys_of).
void expect_object(const Json& j, const Where& w, std::span<const std::string_view> allowed) {
  if (!j.is_object()) w.fail("expected an object, got " + describe(j));
  for (const auto& [k, v] : j.items()) {
    bool known = false;
    for (const auto a : allowed) known = known || a == k;
    if (!known) {
      std::string list;
      for (const auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      w.key(k).fail("unknown key '" + k + "'; expected one of: " + list);
    }
  }
}

const Json& required(const Json& obj, const Where& w, const char* key) {
  const auto it = obj.find(key);
  if (it == obj.end()) w.fail(std::string("missing required key '") + key + "'");
  return *it;
}

const Json* find_key(const Json& obj, const char* key) {
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

double number(const Json& j, const Where& w) {
  if (!j.is_number()) w.fail("expected a number, got " + describe(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) w.fail("not a finite number; expected a finite number");
  return v;
}

bool boolean(const Json& j, const Where& w) {
  if (!j.is_boolean()) w.fail("expected true or false, got " + describe(j));
  return j.get<bool>();
}

// A finite number within the coordinate range (limits::kMaxCoordinate).
double coordinate(const Json& j, const Where& w) {
  const double v = number(j, w);
  if (std::fabs(v) > limits::kMaxCoordinate)
    w.fail("out of range: " + j.dump() + "; coordinates must be finite with magnitude at most " +
           fmt::format("{:g}", limits::kMaxCoordinate) + " (README, \"Limits\")");
  return v;
}

// An array of exactly `dims` (2 or 3) finite numbers; z = 0 when dims is 2. Positions and
// directions (`in_range`) are held to the coordinate range; colours check their own range.
Vec3 vec(const Json& j, const Where& w, size_t dims, bool in_range = true) {
  const std::string expected = "expected an array of " + std::to_string(dims) + " numbers";
  if (!j.is_array() || j.size() != dims) w.fail(expected + ", got " + describe(j));
  double c[3] = {0.0, 0.0, 0.0};
  for (size_t i = 0; i < dims; ++i)
    c[i] = in_range ? coordinate(j[i], w.index(i)) : number(j[i], w.index(i));
  return {c[0], c[1], c[2]};
}

Color color(const Json& j, const Where& w) {
  const Vec3 v = vec(j, w, 3, /*in_range=*/false);
  const Color c{v.x, v.y, v.z};
  for (size_t i = 0; i < 3; ++i)
    if (!(c[i] >= 0.0 && c[i] <= 1.0))
      w.index(i).fail("colour component must be in [0, 1], got " + j[i].dump());
  return c;
}

// Image width or height: a whole number in [1, kMaxImageSide].
int image_side(const Json& j, const Where& w) {
  const double v = number(j, w);
  if (v != std::floor(v)) w.fail("expected a whole number of pixels, got " + j.dump());
  if (v < 1) w.fail("image width and height must be at least 1 pixel, got " + j.dump());
  if (v > kMaxImageSide)
    w.fail("must be at most " + std::to_string(kMaxImageSide) +
           " pixels (the largest supported image side), got " + j.dump());
  return static_cast<int>(v);
}

Camera camera(const Json& j, const Where& w) {
  expect_object(j, w, keys_of("camera"));
  Camera cam;
  cam.eye = vec(required(j, w, "eye"), w.key("eye"), 3);
  cam.target = vec(required(j, w, "target"), w.key("target"), 3);
  cam.up = vec(required(j, w, "up"), w.key("up"), 3);
  cam.fov_deg = number(required(j, w, "fov_deg"), w.key("fov_deg"));
  if (!(cam.fov_deg > 0.0 && cam.fov_deg < 180.0))
    w.key("fov_deg").fail("expected a field of view strictly between 0 and 180 degrees, got " +
                          j["fov_deg"].dump());
  cam.width = image_side(required(j, w, "width"), w.key("width"));
  cam.height = image_side(required(j, w, "height"), w.key("height"));
  // The same limit as --size and --max-side (common/limits.h).
  limits::check_image_size(w.source + ": " + w.path, cam.width, cam.height);
  return cam;
}

// Points and normals of a polyline (curve: dims = 3, texture: dims = 2) and its `closed` flag.
template <class Polyline>
void polyline(const Json& j, const Where& w, size_t dims, const char* kind, Polyline& out) {
  if (const Json* c = find_key(j, "closed")) out.closed = boolean(*c, w.key("closed"));
  if (const Json* sm = find_key(j, "smooth")) out.smooth = boolean(*sm, w.key("smooth"));

  const Where wp = w.key("points");
  const Json& pts = required(j, w, "points");
  if (!pts.is_array()) wp.fail("expected an array of points, got " + describe(pts));
  const size_t min_points = out.closed ? 3 : 2;
  if (pts.size() < min_points)
    wp.fail(std::string("a ") + (out.closed ? "closed " : "") + kind + " needs at least " +
            std::to_string(min_points) + " points, got " + std::to_string(pts.size()) +
            (out.closed ? " (a closed polyline of 2 points would trace one segment twice)" : ""));
  for (size_t i = 0; i < pts.size(); ++i) out.points.push_back(vec(pts[i], wp.index(i), dims));

  // Zero-length segments, including the closing one (reported at its end point, points[0]).
  const size_t n = out.points.size();
  for (size_t b = 1; b <= (out.closed ? n : n - 1); ++b) {
    const size_t a = b - 1;
    if (out.points[a] == out.points[b % n])
      wp.index(b % n).fail("repeated consecutive point (same as points[" + std::to_string(a) +
                           "]); the segment would have zero length" +
                           (b == n ? " (a closed polyline returns to points[0] by itself)" : ""));
  }

  if (const Json* nrm = find_key(j, "normals")) {
    const Where wn = w.key("normals");
    if (!out.smooth)
      wn.fail("normals shape the arcs of a smoothed polyline; with \"smooth\": false every "
              "segment is straight and takes none");
    if (!nrm->is_array()) wn.fail("expected an array of normals, got " + describe(*nrm));
    if (nrm->size() != n)
      wn.fail("expected one normal per point (" + std::to_string(n) + "), got " +
              std::to_string(nrm->size()));
    for (size_t i = 0; i < n; ++i) {
      const Vec3 v = vec((*nrm)[i], wn.index(i), dims);
      if (v == Vec3{}) wn.index(i).fail("normal is the zero vector; expected a non-zero direction");
      out.normals.push_back(v);
    }
  }
  if (const Json* c = find_key(j, "color")) out.color = color(*c, w.key("color"));
}

Curve curve(const Json& j, const Where& w) {
  expect_object(j, w, keys_of("curves[*]"));
  Curve c;
  polyline(j, w, 3, "curve", c);
  return c;
}

Texture texture(const Json& j, const Where& w) {
  expect_object(j, w, keys_of("textures[*]"));
  Texture t;
  polyline(j, w, 2, "texture", t);
  const Json& hw = required(j, w, "half_width");
  t.half_width = coordinate(hw, w.key("half_width"));
  if (!(t.half_width > 0.0))
    w.key("half_width").fail("half_width must be greater than 0, got " + hw.dump());
  if (const Json* jn = find_key(j, "join")) {
    if (!jn->is_string() || (jn->get<std::string>() != "seed" && jn->get<std::string>() != "round"))
      w.key("join").fail("expected \"seed\" or \"round\", got " + describe(*jn));
    t.round_join = jn->get<std::string>() == "round";
  }
  return t;
}

// ---- patches (docs/algorithms.md §4) ----

// A whole number in [lo, hi].
int whole_in(const Json& j, const Where& w, int lo, int hi, const char* what) {
  const double v = number(j, w);
  if (v != std::floor(v)) w.fail(std::string("expected a whole number (") + what + "), got " + j.dump());
  if (v < lo || v > hi)
    w.fail(fmt::format("{} must be in [{}, {}], got {}", what, lo, hi, j.dump()));
  return static_cast<int>(v);
}

// [a, b] of whole numbers in [lo, hi].
std::array<int, 2> whole_pair(const Json& j, const Where& w, int lo, int hi, const char* what) {
  if (!j.is_array() || j.size() != 2)
    w.fail(std::string("expected an array of 2 whole numbers [") + what + " in u, in v], got " +
           describe(j));
  return {whole_in(j[0], w.index(0), lo, hi, what), whole_in(j[1], w.index(1), lo, hi, what)};
}

// `count` control points (3-D positions).
std::vector<Vec3> control_points(const Json& j, const Where& w, size_t count, const std::string& why) {
  if (!j.is_array()) w.fail("expected an array of control points, got " + describe(j));
  if (j.size() != count)
    w.fail(fmt::format("expected {} control points ({}), got {}", count, why, j.size()));
  std::vector<Vec3> pts;
  pts.reserve(count);
  for (size_t i = 0; i < count; ++i) pts.push_back(vec(j[i], w.index(i), 3));
  return pts;
}

// A clamped, non-decreasing knot vector of size + degree + 1 values: the first and the last
// degree + 1 knots equal, interior knots of multiplicity at most `degree` (the surface stays
// connected), a parameter interval of non-zero length.
std::vector<double> knot_vector(const Json& j, const Where& w, int degree, int size, char dir) {
  const size_t count = static_cast<size_t>(size + degree + 1);
  if (!j.is_array()) w.fail("expected an array of knots, got " + describe(j));
  if (j.size() != count)
    w.fail(fmt::format("expected {} knots (size_{} + degree_{} + 1 = {} + {} + 1), got {}", count,
                       dir, dir, size, degree, j.size()));
  std::vector<double> k;
  k.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    k.push_back(coordinate(j[i], w.index(i)));
    if (i > 0 && k[i] < k[i - 1])
      w.index(i).fail(fmt::format("knots must be non-decreasing; {} follows {} at knots_{}[{}]",
                                  j[i].dump(), j[i - 1].dump(), dir, i - 1));
  }
  const size_t p = static_cast<size_t>(degree);
  for (size_t i = 1; i <= p; ++i) {
    if (k[i] != k[0])
      w.index(i).fail(fmt::format("the knot vector must be clamped: the first degree + 1 = {} knots "
                                  "must be equal, got {} after {}", p + 1, j[i].dump(), j[0].dump()));
    if (k[count - 1 - i] != k[count - 1])
      w.index(count - 1 - i)
          .fail(fmt::format("the knot vector must be clamped: the last degree + 1 = {} knots must "
                            "be equal, got {} before {}", p + 1, j[count - 1 - i].dump(),
                            j[count - 1].dump()));
  }
  if (!(k[0] < k[count - 1]))
    w.fail(fmt::format("the parameter interval is empty: every knot is {}", j[0].dump()));
  for (size_t i = p + 1; i + p + 1 < count;) {
    size_t m = 1;
    while (i + m + p + 1 < count && k[i + m] == k[i]) ++m;
    if (k[i] == k[0] || k[i] == k[count - 1])
      w.index(i).fail(fmt::format("interior knot {} equals the clamped end knot; an end knot may "
                                  "appear degree + 1 = {} times", j[i].dump(), p + 1));
    if (m > p)
      w.index(i).fail(fmt::format("interior knot {} repeats {} times; at most degree = {} (the "
                                  "surface would fall apart)", j[i].dump(), m, p));
    i += m;
  }
  return k;
}

// Refuses the scene's patch number `count` (1-based) past limits::kMaxPatches, at the JSON path
// of the member that crosses it.
void check_patch_count(size_t count, const Where& w) {
  if (count > static_cast<size_t>(limits::kMaxPatches))
    w.fail(fmt::format("too many patches: this is patch {} of the scene; at most {} patches per "
                       "scene, a bezier_set's members counted one by one (README, \"Limits\")",
                       count, limits::kMaxPatches));
}

// `before`: the patches of the objects before this one (the limit counts the whole scene).
std::vector<Patch> patch_object(const Json& j, const Where& w, size_t before) {
  if (!j.is_object()) w.fail("expected an object, got " + describe(j));
  const Json& t = required(j, w, "type");
  if (!t.is_string()) w.key("type").fail("expected a string (bezier, bspline, nurbs or bezier_set), got " + describe(t));
  const std::string type = t.get<std::string>();
  if (type == "bezier") {
    expect_object(j, w, keys_of("patches[*] type bezier"));
  } else if (type == "bezier_set") {
    expect_object(j, w, keys_of("patches[*] type bezier_set"));
  } else if (type == "bspline") {
    expect_object(j, w, keys_of("patches[*] type bspline"));
  } else if (type == "nurbs") {
    expect_object(j, w, keys_of("patches[*] type nurbs"));
  } else {
    w.key("type").fail("unknown patch type " + t.dump() + "; expected bezier, bspline, nurbs or bezier_set");
  }
  Patch p;
  const auto deg = whole_pair(required(j, w, "degree"), w.key("degree"), 1, limits::kMaxPatchDegree, "degree");
  p.degree_u = deg[0], p.degree_v = deg[1];
  if (const Json* c = find_key(j, "color")) p.color = color(*c, w.key("color"));

  if (type == "bezier" || type == "bezier_set") {
    p.type = PatchType::kBezier;
    p.size_u = p.degree_u + 1, p.size_v = p.degree_v + 1;
    const size_t count = static_cast<size_t>(p.size_u * p.size_v);
    const std::string why = fmt::format("(degree_u + 1)·(degree_v + 1) = {}·{}", p.size_u, p.size_v);
    if (type == "bezier") {
      p.control_points = control_points(required(j, w, "control_points"), w.key("control_points"), count, why);
      return {p};
    }
    const Json& set = required(j, w, "patches");
    const Where ws = w.key("patches");
    if (!set.is_array()) ws.fail("expected an array of patches (arrays of control points), got " + describe(set));
    if (set.empty()) ws.fail("expected at least one patch, got an empty array");
    std::vector<Patch> out;
    out.reserve(std::min<size_t>(set.size(), limits::kMaxPatches));
    for (size_t i = 0; i < set.size(); ++i) {
      check_patch_count(before + i + 1, ws.index(i));
      out.push_back(p);
      out.back().control_points = control_points(set[i], ws.index(i), count, why);
    }
    return out;
  }

  p.type = type == "nurbs" ? PatchType::kNurbs : PatchType::kBSpline;
  const Where wsz = w.key("size");
  const auto size = whole_pair(required(j, w, "size"), wsz, 2, 1 << 20, "control points per direction");
  p.size_u = size[0], p.size_v = size[1];
  if (p.size_u < p.degree_u + 1)
    wsz.index(0).fail(fmt::format("a degree-{} direction needs at least {} control points, got {}",
                                  p.degree_u, p.degree_u + 1, p.size_u));
  if (p.size_v < p.degree_v + 1)
    wsz.index(1).fail(fmt::format("a degree-{} direction needs at least {} control points, got {}",
                                  p.degree_v, p.degree_v + 1, p.size_v));
  const long long count = static_cast<long long>(p.size_u) * p.size_v;
  const Json& cp = required(j, w, "control_points");
  if (cp.is_array() && static_cast<long long>(cp.size()) != count)
    w.key("control_points").fail(fmt::format("expected {} control points (size {}·{}), got {}", count,
                                             p.size_u, p.size_v, cp.size()));
  p.control_points = control_points(cp, w.key("control_points"), static_cast<size_t>(count),
                                    fmt::format("size {}·{}", p.size_u, p.size_v));
  p.knots_u = knot_vector(required(j, w, "knots_u"), w.key("knots_u"), p.degree_u, p.size_u, 'u');
  p.knots_v = knot_vector(required(j, w, "knots_v"), w.key("knots_v"), p.degree_v, p.size_v, 'v');
  if (p.type == PatchType::kNurbs) {
    const Where ww = w.key("weights");
    const Json& wj = required(j, w, "weights");
    if (!wj.is_array()) ww.fail("expected an array of weights, got " + describe(wj));
    if (static_cast<long long>(wj.size()) != count)
      ww.fail(fmt::format("expected one weight per control point ({}), got {}", count, wj.size()));
    for (size_t i = 0; i < wj.size(); ++i) {
      const double v = coordinate(wj[i], ww.index(i));
      if (!(v > 0.0)) ww.index(i).fail("weights must be greater than 0, got " + wj[i].dump());
      p.weights.push_back(v);
    }
  }
  return {p};
}

std::vector<Patch> patches(const Json& j, const Where& w) {
  if (!j.is_array()) w.fail("expected an array of patches, got " + describe(j));
  std::vector<Patch> out;
  for (size_t i = 0; i < j.size(); ++i) {
    check_patch_count(out.size() + 1, w.index(i));
    for (Patch& p : patch_object(j[i], w.index(i), out.size())) out.push_back(std::move(p));
  }
  return out;
}

// ---- surfaces (docs/algorithms.md §3, seed 004; docs/surfaces.md) ----

// Smallest accepted size parameter and scale: below it the local frame's 1/scale and the
// indicators' (x/a)² leave the range the coordinate limit is meant to keep (limits.h).
constexpr double kMinSurfaceSize = 1e-9;

// The hardware's phi_max limit: 8 turns (docs/algorithms.md §3, the spiral and snail turn counter).
constexpr double kMaxSurfaceTurns = 8.0;

// A surface parameter: a finite number with |v| <= limits::kMaxCoordinate.
double surface_number(const Json& j, const Where& w) {
  const double v = number(j, w);
  if (std::fabs(v) > limits::kMaxCoordinate)
    w.fail("out of range: " + j.dump() + "; surface parameters must be finite with magnitude at "
           "most " + fmt::format("{:g}", limits::kMaxCoordinate) + " (README, \"Limits\")");
  return v;
}

// A size parameter: > 0 (at least kMinSurfaceSize), within the coordinate range.
double surface_size(const Json& j, const Where& w, const char* what) {
  const double v = surface_number(j, w);
  if (!(v > 0.0)) w.fail(std::string(what) + " must be greater than 0, got " + j.dump());
  if (v < kMinSurfaceSize)
    w.fail(fmt::format("{} is too small to compute with: {}; at least {:g}", what, j.dump(),
                       kMinSurfaceSize));
  return v;
}

SurfaceType surface_type(const Json& obj, const Where& w) {
  const Json& t = required(obj, w, "type");
  constexpr const char* kTypes = "ellipsoid, relief_ellipsoid, spiral, snail or rocket";
  if (!t.is_string()) w.key("type").fail(std::string("expected a string (") + kTypes + "), got " + describe(t));
  const std::string name = t.get<std::string>();
  for (const SurfaceType s : {SurfaceType::kEllipsoid, SurfaceType::kReliefEllipsoid,
                              SurfaceType::kSpiral, SurfaceType::kSnail, SurfaceType::kRocket})
    if (name == surface_type_name(s)) return s;
  w.key("type").fail("unknown surface type " + t.dump() + "; expected " + kTypes);
}

Surface surface(const Json& j, const Where& w) {
  if (!j.is_object()) w.fail("expected an object, got " + describe(j));
  const SurfaceType type = surface_type(j, w);
  switch (type) {
    case SurfaceType::kEllipsoid:
      expect_object(j, w, keys_of("surfaces[*] type ellipsoid"));
      break;
    case SurfaceType::kReliefEllipsoid:
      expect_object(j, w, keys_of("surfaces[*] type relief_ellipsoid"));
      break;
    case SurfaceType::kSpiral:
      expect_object(j, w, keys_of("surfaces[*] type spiral"));
      break;
    case SurfaceType::kSnail:
      expect_object(j, w, keys_of("surfaces[*] type snail"));
      break;
    case SurfaceType::kRocket:
      expect_object(j, w, keys_of("surfaces[*] type rocket"));
      break;
  }
  Surface s;
  s.type = type;
  s.p = default_surface_params(type);
  SurfaceParams& p = s.p;
  const char* name = surface_type_name(type);

  // Placement.
  if (const Json* v = find_key(j, "position")) s.position = vec(*v, w.key("position"), 3);
  if (const Json* v = find_key(j, "rotation_deg")) {
    const Where wr = w.key("rotation_deg");
    if (!v->is_array() || v->size() != 3)
      wr.fail("expected an array of 3 numbers (degrees about x, y, z), got " + describe(*v));
    s.rotation_deg = {surface_number((*v)[0], wr.index(0)), surface_number((*v)[1], wr.index(1)),
                      surface_number((*v)[2], wr.index(2))};
  }
  if (const Json* v = find_key(j, "scale")) {
    const Where ws = w.key("scale");
    s.scale = surface_number(*v, ws);
    if (s.scale == 0.0) ws.fail("scale of 0; expected a uniform scale greater than 0");
    if (!(s.scale > 0.0)) ws.fail("scale must be greater than 0, got " + v->dump());
    if (s.scale < kMinSurfaceSize)
      ws.fail(fmt::format("scale is too small to compute with: {}; at least {:g}", v->dump(),
                          kMinSurfaceSize));
  }
  if (const Json* v = find_key(j, "color")) s.color = color(*v, w.key("color"));

  // Parameters: each optional, the seed's default otherwise (default_surface_params).
  const auto size = [&](const char* key, double& out) {
    if (const Json* v = find_key(j, key)) out = surface_size(*v, w.key(key), key);
  };
  const auto any = [&](const char* key, double& out) {
    if (const Json* v = find_key(j, key)) out = surface_number(*v, w.key(key));
  };
  const auto phi_max = [&] {
    const Json* v = find_key(j, "phi_max");
    if (!v) return;
    const Where wp = w.key("phi_max");
    p.phi_max = surface_number(*v, wp);
    if (!(p.phi_max > 0.0)) wp.fail("phi_max must be greater than 0, got " + v->dump());
    if (p.phi_max > kMaxSurfaceTurns * 2.0 * std::numbers::pi)
      wp.fail(fmt::format("phi_max must be at most 16π = {:.6g} (the hardware follows at most {:g} "
                          "turns), got {}", kMaxSurfaceTurns * 2.0 * std::numbers::pi,
                          kMaxSurfaceTurns, v->dump()));
  };
  const auto y_range = [&] {
    // Default: the type's range in units of b (docs/scene-format.md), for the b read above.
    p.y_min = -p.b;
    p.y_max = type == SurfaceType::kEllipsoid ? 0.5 * p.b : p.b;
    const Json* v = find_key(j, "y_range");
    if (!v) return;
    const Where wy = w.key("y_range");
    if (!v->is_array() || v->size() != 2)
      wy.fail("expected an array of 2 numbers [lo, hi], got " + describe(*v));
    p.y_min = surface_number((*v)[0], wy.index(0));
    p.y_max = surface_number((*v)[1], wy.index(1));
    if (!(p.y_min < p.y_max))
      wy.fail(fmt::format("the range is empty or inverted: lo = {} must be less than hi = {}",
                          (*v)[0].dump(), (*v)[1].dump()));
    if (p.y_min < -p.b || p.y_max > p.b)
      wy.fail(fmt::format("the range must lie within [-b, b] = [{:g}, {:g}] (the {} has no section "
                          "outside), got {}", -p.b, p.b, name, v->dump()));
  };

  switch (type) {
    case SurfaceType::kEllipsoid:
      size("a", p.a), size("b", p.b), size("c", p.c);
      y_range();
      break;
    case SurfaceType::kReliefEllipsoid:
      size("a", p.a), size("b", p.b), size("c", p.c);
      any("d", p.d), any("e", p.e);
      if (!(p.d > std::fabs(p.e)))
        w.key(find_key(j, "d") ? "d" : "e")
            .fail(fmt::format("the relief needs d > |e| so that k = d + e·sin 10φ·cos 9y stays "
                              "above 0; got d = {:g}, e = {:g}", p.d, p.e));
      y_range();
      break;
    case SurfaceType::kSpiral: {
      any("R", p.R), any("k", p.k);
      size("a", p.a), size("b", p.b), size("c", p.c);
      phi_max();
      // R + aφ is linear in φ: its smallest value on [0, phi_max] is at an end (with a > 0, R).
      // Named at R when the file gives it, else at the larger of b and c.
      const double nearest = std::min(p.R, p.R + p.a * p.phi_max);
      if (!(nearest > std::max(p.b, p.c)))
        w.key(find_key(j, "R") ? "R" : p.b >= p.c ? "b" : "c")
            .fail(fmt::format("the section reaches the axis: R + a·φ must exceed max(b, c) = {:g} "
                              "for every φ in [0, phi_max], got {:g}", std::max(p.b, p.c), nearest));
      break;
    }
    case SurfaceType::kSnail:
      size("a", p.a);
      phi_max();
      break;
    case SurfaceType::kRocket:
      size("a", p.a), size("b", p.b), size("c", p.c), size("e", p.e);
      if (const Json* v = find_key(j, "d")) {
        p.d = surface_number(*v, w.key("d"));
        if (!(p.d >= 0.0)) w.key("d").fail("d (the fins' radius increase) must be at least 0, got " + v->dump());
      }
      break;
  }

  // The whole surface must stay in the coordinate range (its world bounding sphere).
  const CompiledSurface c = compile_surface(s, 0);
  const double reach = std::max({std::fabs(c.centre.x), std::fabs(c.centre.y), std::fabs(c.centre.z)}) + c.radius;
  if (!(reach <= limits::kMaxCoordinate))
    w.fail(fmt::format("the {} reaches {:.3g} from the origin (bounding radius {:.3g} in world "
                       "units); coordinates must stay within {:g} (README, \"Limits\")",
                       name, reach, c.radius, limits::kMaxCoordinate));
  return s;
}

// An array whose elements are read by `element`.
template <class T, class F>
std::vector<T> array_of(const Json& j, const Where& w, const char* what, F element) {
  if (!j.is_array()) w.fail(std::string("expected an array of ") + what + ", got " + describe(j));
  std::vector<T> out;
  for (size_t i = 0; i < j.size(); ++i) out.push_back(element(j[i], w.index(i)));
  return out;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& source) {
  const Json j = parse_json(text, source);
  const Where top{source, ""};
  if (!j.is_object())
    top.fail("expected a JSON object at the top level, got " + describe(j));
  expect_object(j, top, keys_of("top level"));

  Scene scene;
  scene.source = source;
  if (const Json* a = find_key(j, "about"); a && !a->is_string())
    top.key("about").fail("expected a string (a free description), got " + describe(*a));
  if (const Json* a = find_key(j, "about")) scene.about = a->get<std::string>();
  scene.camera = camera(required(j, top, "camera"), top.key("camera"));
  if (const Json* b = find_key(j, "background"))
    scene.background = color(*b, top.key("background"));
  if (const Json* c = find_key(j, "curves"))
    scene.curves = array_of<Curve>(*c, top.key("curves"), "curves", curve);
  if (const Json* t = find_key(j, "textures"))
    scene.textures = array_of<Texture>(*t, top.key("textures"), "textures", texture);
  if (const Json* s = find_key(j, "surfaces")) {
    if (s->is_array() && s->size() > static_cast<size_t>(limits::kMaxSurfaces))
      top.key("surfaces").fail(fmt::format("too many surfaces: {}; at most {} per scene (README, "
                                           "\"Limits\")", s->size(), limits::kMaxSurfaces));
    scene.surfaces = array_of<Surface>(*s, top.key("surfaces"), "surfaces", surface);
  }
  if (const Json* p = find_key(j, "patches")) scene.patches = patches(*p, top.key("patches"));
  return scene;
}

Scene load_scene(const std::string& path) {
  return parse_scene(read_input_file(path, "scene file"), path);
}

}  // namespace rpu::scene
