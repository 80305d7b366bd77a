#include "patch/volume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "common/parallel.h"
#include "patch/patch_surface.h"

namespace rpu::patch {
namespace {

double binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  double c = 1.0;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

// ∫₀¹ B_{i,p} B_{j,q} B_{k,r} dt = C(p,i) C(q,j) C(r,k) / ((N + 1) · C(N, s)), N = p + q + r,
// s = i + j + k (the Beta integral ∫ t^s (1 − t)^(N − s) dt = 1 / ((N + 1) C(N, s))). Indices out
// of range give 0, so the derivative formula below needs no special cases.
double bernstein_triple(int i, int p, int j, int q, int k, int r) {
  if (i < 0 || i > p || j < 0 || j > q || k < 0 || k > r) return 0.0;
  const int N = p + q + r, s = i + j + k;
  return binomial(p, i) * binomial(q, j) * binomial(r, k) / ((N + 1) * binomial(N, s));
}

// Table T[d][a1][a2][a3] = ∫ B_a1 B_a2 B_a3 with the factor d (0, 1, 2) replaced by its
// derivative B'_{a,n} = n (B_{a−1,n−1} − B_{a,n−1}) (the integrals of eq 25, closed form as eq 27).
struct TripleTable {
  int n = 0;
  std::vector<double> t;  // [d][a1][a2][a3]
  explicit TripleTable(int degree) : n(degree), t(3 * (n + 1) * (n + 1) * (n + 1)) {
    for (int d = 0; d < 3; ++d)
      for (int a1 = 0; a1 <= n; ++a1)
        for (int a2 = 0; a2 <= n; ++a2)
          for (int a3 = 0; a3 <= n; ++a3) {
            std::array<int, 3> a{a1, a2, a3};
            auto with = [&](int shift) {
              std::array<int, 3> idx = a, deg{n, n, n};
              idx[d] -= shift;
              deg[d] = n - 1;
              return bernstein_triple(idx[0], deg[0], idx[1], deg[1], idx[2], deg[2]);
            };
            at(d, a1, a2, a3) = n * (with(1) - with(0));
          }
  }
  double& at(int d, int a1, int a2, int a3) {
    return t[((d * (n + 1) + a1) * (n + 1) + a2) * (n + 1) + a3];
  }
  double get(int d, int a1, int a2, int a3) const {
    return t[((d * (n + 1) + a1) * (n + 1) + a2) * (n + 1) + a3];
  }
};

// Gauss–Legendre nodes and weights on [0, 1] (Newton on P_k from the Chebyshev guesses).
void gauss_legendre(int k, std::vector<double>& x, std::vector<double>& w) {
  x.assign(k, 0.0);
  w.assign(k, 0.0);
  for (int i = 0; i < k; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (k + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int m = 2; m <= k; ++m) {
        const double p2 = ((2 * m - 1) * z * p1 - (m - 1) * p0) / m;
        p0 = p1;
        p1 = p2;
      }
      if (k == 1) p0 = 1, p1 = z;
      dp = k * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    double p0 = 1, p1 = z;
    for (int m = 2; m <= k; ++m) {
      const double p2 = ((2 * m - 1) * z * p1 - (m - 1) * p0) / m;
      p0 = p1;
      p1 = p2;
    }
    dp = k * (z * p1 - p0) / (z * z - 1);
    x[i] = 0.5 * (1 - z);
    w[i] = 1.0 / ((1 - z * z) * dp * dp);  // 2/((1−z²)P'²) on [−1,1], halved for [0,1]
  }
}

// Eq 21's integrand ½(x·A + y·B) at one point.
double thesis_integrand(const SurfacePoint& s) {
  const double A = s.du.y * s.dv.z - s.du.z * s.dv.y;
  const double B = s.du.z * s.dv.x - s.du.x * s.dv.z;
  return 0.5 * (s.p.x * A + s.p.y * B);
}

constexpr const char* kEdgeName[4] = {"v = 0", "u = 1", "v = 1", "u = 0"};

}  // namespace

void require_bezier(const std::vector<scene::Patch>& patches, const std::string& source) {
  if (patches.empty()) throw Error(source, "the scene has no patches, so it encloses no volume");
  for (size_t k = 0; k < patches.size(); ++k) {
    const auto& p = patches[k];
    const std::string where = source + ": patches[" + std::to_string(k) + "]";
    if (p.type != scene::PatchType::kBezier)
      throw Error(where, std::string("is a ") +
                             (p.type == scene::PatchType::kBSpline ? "B-spline" : "NURBS") +
                             " patch; volumes are computed for Bézier patches only");
    if (p.degree_u < 1 || p.degree_v < 1 || p.size_u != p.degree_u + 1 ||
        p.size_v != p.degree_v + 1 ||
        p.control_points.size() != static_cast<size_t>(p.size_u) * p.size_v)
      throw Error(where, "not a complete Bézier control net");
  }
}

double exact_volume(const std::vector<scene::Patch>& patches) {
  // The tables of every degree first (shared, read-only), then one sum per patch on all cores,
  // added in patch order (the result does not depend on the threads).
  std::vector<TripleTable> tables;
  const auto table = [&](int n) -> const TripleTable& {
    for (const auto& t : tables)
      if (t.n == n) return t;
    throw Error("exact volume", "no table of degree " + std::to_string(n));
  };
  for (const auto& p : patches)
    for (int n : {p.degree_u, p.degree_v})
      if (std::none_of(tables.begin(), tables.end(), [&](const TripleTable& t) { return t.n == n; }))
        tables.emplace_back(n);
  std::vector<double> per_patch(patches.size(), 0.0);
  parallel_rows(
      static_cast<int>(patches.size()), 0,
      [&](int k) {
        const scene::Patch& p = patches[static_cast<size_t>(k)];
        const int n = p.degree_u, m = p.degree_v;
        const TripleTable& tu = table(n);
        const TripleTable& tv = table(m);
        const auto& c = p.control_points;
        double sum = 0;
        // ½ Σ X1 Y2 Z3 [Iu(Y')·Iv(Z') − Iu(Z')·Iv(Y') + Iu(Z')·Iv(X') − Iu(X')·Iv(Z')]  (eq 25)
        for (int a1 = 0; a1 <= n; ++a1)
          for (int b1 = 0; b1 <= m; ++b1) {
            const double x = c[a1 * (m + 1) + b1].x;
            for (int a2 = 0; a2 <= n; ++a2)
              for (int b2 = 0; b2 <= m; ++b2) {
                const double xy = x * c[a2 * (m + 1) + b2].y;
                for (int a3 = 0; a3 <= n; ++a3)
                  for (int b3 = 0; b3 <= m; ++b3) {
                    const double z = c[a3 * (m + 1) + b3].z;
                    const double w = tu.get(1, a1, a2, a3) * tv.get(2, b1, b2, b3) -
                                     tu.get(2, a1, a2, a3) * tv.get(1, b1, b2, b3) +
                                     tu.get(2, a1, a2, a3) * tv.get(0, b1, b2, b3) -
                                     tu.get(0, a1, a2, a3) * tv.get(2, b1, b2, b3);
                    sum += xy * z * w;
                  }
              }
          }
        per_patch[static_cast<size_t>(k)] = 0.5 * sum;
      },
      [](auto&) {});
  double volume = 0;
  for (double v : per_patch) volume += v;
  return volume;
}

double exact_volume_gauss(const std::vector<scene::Patch>& patches) {
  double volume = 0;
  std::vector<double> xu, wu, xv, wv;
  for (const auto& p : patches) {
    const PatchSurface surface(p);
    // Degree of S·(S_u × S_v) in u is 3·degree_u − 1; k Gauss points integrate degree 2k − 1.
    gauss_legendre((3 * p.degree_u + 2) / 2, xu, wu);
    gauss_legendre((3 * p.degree_v + 2) / 2, xv, wv);
    double sum = 0;
    for (size_t i = 0; i < xu.size(); ++i)
      for (size_t j = 0; j < xv.size(); ++j) {
        const SurfacePoint s = surface.evaluate(xu[i], xv[j]);
        sum += wu[i] * wv[j] * dot(s.p, cross(s.du, s.dv));
      }
    volume += sum / 3.0;
  }
  return volume;
}

double graphical_volume(const std::vector<scene::Patch>& patches, int n, int m,
                        GraphicalNodes nodes) {
  if (n < 2 || m < 2) throw Error("graphical integration", "needs at least 2 x 2 nodes");
  auto node = [&](int i, int count) {
    return nodes == GraphicalNodes::kMidpoint ? (i + 0.5) / count
                                              : static_cast<double>(i) / (count - 1);  // eq 24
  };
  // One sum per patch on all cores, added in patch order.
  std::vector<double> per_patch(patches.size(), 0.0);
  parallel_rows(
      static_cast<int>(patches.size()), 0,
      [&](int k) {
        const PatchSurface surface(patches[static_cast<size_t>(k)]);
        double sum = 0;
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < m; ++j) sum += thesis_integrand(surface.evaluate(node(i, n), node(j, m)));
        per_patch[static_cast<size_t>(k)] = sum / (static_cast<double>(n) * m);  // eq 23 (½ in the integrand)
      },
      [](auto&) {});
  double volume = 0;
  for (double v : per_patch) volume += v;
  return volume;
}

SliceVolume slice_volume(const std::vector<scene::Patch>& patches, int slices, int grid) {
  if (slices < 1) throw Error("slices", "needs at least one slice");
  if (grid < 1) throw Error("slices", "needs a tessellation grid of at least 1");
  const int count = static_cast<int>(patches.size());
  const int side = grid + 1;
  // Two passes over every patch's (grid + 1)² samples, one row of samples at a time, so that the
  // memory does not grow with the patches or the grid squared: the z range first, then the
  // sections. Each pass evaluates the same points in the same order, so the planes and the
  // areas are those of one stored tessellation.
  const auto sample_row = [&](const PatchSurface& surface, int a, std::vector<Vec3>& row) {
    row.resize(static_cast<size_t>(side));
    for (int b = 0; b <= grid; ++b)
      row[static_cast<size_t>(b)] =
          surface.point(static_cast<double>(a) / grid, static_cast<double>(b) / grid);
  };
  std::vector<double> lo(static_cast<size_t>(count)), hi(static_cast<size_t>(count));
  parallel_rows(
      count, 0,
      [&, row = std::vector<Vec3>()](int k) mutable {
        const PatchSurface surface(patches[static_cast<size_t>(k)]);
        double l = std::numeric_limits<double>::infinity(), h = -l;
        for (int a = 0; a <= grid; ++a) {
          sample_row(surface, a, row);
          for (const Vec3& q : row) l = std::min(l, q.z), h = std::max(h, q.z);
        }
        lo[static_cast<size_t>(k)] = l, hi[static_cast<size_t>(k)] = h;
      },
      [](auto&) {});
  SliceVolume out;
  out.slices = slices;
  out.z_min = std::numeric_limits<double>::infinity();
  out.z_max = -out.z_min;
  for (int k = 0; k < count; ++k) {
    out.z_min = std::min(out.z_min, lo[static_cast<size_t>(k)]);
    out.z_max = std::max(out.z_max, hi[static_cast<size_t>(k)]);
  }
  if (!(out.z_max > out.z_min)) return out;  // flat or empty: no volume
  const double h = (out.z_max - out.z_min) / slices, nudge = 1e-9 * (out.z_max - out.z_min);
  // Planes, sorted: trapezoid planes at the K + 1 interval ends (the two outermost nudged
  // inside), Cavalieri planes at the K slab middles.
  std::vector<double> planes;
  for (int k = 0; k <= slices; ++k)
    planes.push_back(k == 0 ? out.z_min + nudge
                            : (k == slices ? out.z_max - nudge : out.z_min + k * h));
  for (int k = 0; k < slices; ++k) planes.push_back(out.z_min + (k + 0.5) * h);
  std::vector<int> order(planes.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return planes[a] < planes[b]; });
  std::vector<double> sorted(planes.size());
  for (size_t i = 0; i < order.size(); ++i) sorted[i] = planes[order[i]];

  auto triangle = [&](const Vec3& p0, const Vec3& p1, const Vec3& p2, std::vector<double>& acc) {
    const double lo = std::min({p0.z, p1.z, p2.z}), hi = std::max({p0.z, p1.z, p2.z});
    const Vec3 nrm = cross(p1 - p0, p2 - p0);
    const Vec3 along{-nrm.y, nrm.x, 0.0};  // e_z × n: the direction the section runs in
    const Vec3 v[3] = {p0, p1, p2};
    for (auto it = std::lower_bound(sorted.begin(), sorted.end(), lo);
         it != sorted.end() && *it <= hi; ++it) {
      const double z0 = *it;
      Vec3 ends[2];
      int found = 0;
      for (int e = 0; e < 3 && found < 2; ++e) {
        const Vec3& a = v[e];
        const Vec3& b = v[(e + 1) % 3];
        if ((a.z >= z0) != (b.z >= z0)) ends[found++] = a + (b - a) * ((z0 - a.z) / (b.z - a.z));
      }
      if (found < 2) continue;
      Vec3 a = ends[0], b = ends[1];
      if (dot(b - a, along) < 0) std::swap(a, b);
      acc[it - sorted.begin()] += 0.5 * (a.x * b.y - b.x * a.y);  // shoelace
    }
  };
  // Sums per block of consecutive patches, each block in patch order, the blocks added in order
  // afterwards: the result does not depend on the threads. The blocks' sums take at most about
  // kSliceSumBytes.
  constexpr size_t kSliceSumBytes = size_t{32} << 20;
  const int blocks = static_cast<int>(std::clamp<size_t>(
      kSliceSumBytes / (planes.size() * sizeof(double)), 1, std::min<size_t>(count, 256)));
  std::vector<std::vector<double>> per_block(static_cast<size_t>(blocks));
  parallel_rows(
      blocks, 0,
      [&, r0 = std::vector<Vec3>(), r1 = std::vector<Vec3>()](int block) mutable {
        std::vector<double> acc(planes.size(), 0.0);
        const int first = static_cast<int>(static_cast<long long>(block) * count / blocks);
        const int last = static_cast<int>(static_cast<long long>(block + 1) * count / blocks);
        for (int k = first; k < last; ++k) {
          const PatchSurface surface(patches[static_cast<size_t>(k)]);
          sample_row(surface, 0, r0);
          for (int a = 0; a < grid; ++a) {
            sample_row(surface, a + 1, r1);
            for (int b = 0; b < grid; ++b) {
              const Vec3& p00 = r0[static_cast<size_t>(b)];
              const Vec3& p10 = r1[static_cast<size_t>(b)];
              const Vec3& p01 = r0[static_cast<size_t>(b) + 1];
              const Vec3& p11 = r1[static_cast<size_t>(b) + 1];
              // Vertex order keeps the orientation of S_u × S_v.
              triangle(p00, p10, p11, acc);
              triangle(p00, p11, p01, acc);
            }
            std::swap(r0, r1);
          }
        }
        per_block[static_cast<size_t>(block)] = std::move(acc);
      },
      [](auto&) {});
  std::vector<double> area(planes.size(), 0.0);
  for (const auto& acc : per_block)
    for (size_t i = 0; i < acc.size(); ++i) area[i] += acc[i];
  std::vector<double> by_plane(planes.size());
  for (size_t i = 0; i < order.size(); ++i) by_plane[order[i]] = area[i];
  double trap = 0.5 * (by_plane[0] + by_plane[slices]);
  for (int k = 1; k < slices; ++k) trap += by_plane[k];
  out.trapezoid = h * trap;
  double cav = 0;
  for (int k = 0; k < slices; ++k) cav += by_plane[slices + 1 + k];
  out.cavalieri = h * cav;
  return out;
}

long long volume_work(const std::vector<scene::Patch>& patches, int slice_grid, int slices) {
  // An evaluation costs its control points plus a fixed part (the bases), kEvaluationOverhead
  // points' worth; cutting a triangle by the planes costs as much.
  constexpr long long kEvaluationOverhead = 16;
  const long long g = slice_grid, planes = 2LL * slices + 1;
  long long work = 0;
  for (const auto& p : patches) {
    const long long points = static_cast<long long>(p.degree_u + 1) * (p.degree_v + 1);
    const long long evaluation = points + kEvaluationOverhead;
    const long long gauss = static_cast<long long>((3 * p.degree_u + 2) / 2) * ((3 * p.degree_v + 2) / 2);
    work += points * points * points;                                 // exact sums (eq 25)
    work += gauss * evaluation;                                       // Gauss–Legendre check
    work += 2 * (10 * 10 + 100 * 100) * evaluation;                   // graphical, both node rules
    work += 2 * (g + 1) * (g + 1) * evaluation;                       // slices: two passes
    work += (2 * g * g + planes * 4 * g) * kEvaluationOverhead;       // triangles and crossings
  }
  return work;
}

ClosureReport check_closed_surface(const std::vector<scene::Patch>& patches,
                                   double relative_tolerance, bool allow_z_planar_openings) {
  constexpr int kSamples = 9;
  using Edge = std::array<Vec3, kSamples>;
  ClosureReport report;
  if (patches.empty()) return report;
  Vec3 lo = patches[0].control_points.at(0), hi = lo;
  for (const auto& p : patches)
    for (const auto& c : p.control_points) {
      lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
      hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
    }
  const double tol = relative_tolerance * std::max(length(hi - lo), 1e-300);

  std::vector<Edge> edges;  // patch k, edge e at 4k + e, counterclockwise in (u, v)
  std::vector<bool> collapsed;
  for (const auto& p : patches) {
    const PatchSurface surface(p);
    for (int e = 0; e < 4; ++e) {
      Edge edge;
      for (int s = 0; s < kSamples; ++s) {
        const double t = static_cast<double>(s) / (kSamples - 1);
        const double u = e == 0 ? t : e == 1 ? 1.0 : e == 2 ? 1.0 - t : 0.0;
        const double v = e == 0 ? 0.0 : e == 1 ? t : e == 2 ? 1.0 : 1.0 - t;
        edge[s] = surface.point(u, v);
      }
      bool flat = true;
      for (const auto& q : edge) flat = flat && length(q - edge[0]) <= tol;
      edges.push_back(edge);
      collapsed.push_back(flat);
    }
  }
  auto matches = [&](const Edge& a, const Edge& b, bool reversed) {
    for (int s = 0; s < kSamples; ++s)
      if (length(a[s] - b[reversed ? kSamples - 1 - s : s]) > tol) return false;
    return true;
  };
  auto name = [&](size_t e) {
    return "patches[" + std::to_string(e / 4) + "]: edge " + kEdgeName[e % 4];
  };
  // Candidates by the x of the edge's middle sample (a partner's middle is the same point).
  std::vector<size_t> by_mid(edges.size());
  for (size_t e = 0; e < edges.size(); ++e) by_mid[e] = e;
  auto mid_x = [&](size_t e) { return edges[e][kSamples / 2].x; };
  std::sort(by_mid.begin(), by_mid.end(), [&](size_t a, size_t b) { return mid_x(a) < mid_x(b); });
  for (size_t e = 0; e < edges.size(); ++e) {
    if (collapsed[e]) continue;
    bool partner = false;
    auto first = std::lower_bound(by_mid.begin(), by_mid.end(), mid_x(e) - tol,
                                  [&](size_t a, double x) { return mid_x(a) < x; });
    for (auto it = first; it != by_mid.end() && mid_x(*it) <= mid_x(e) + tol; ++it) {
      const size_t f = *it;
      if (f == e || collapsed[f]) continue;
      if (length(edges[e][kSamples / 2] - edges[f][kSamples / 2]) > tol) continue;  // quick reject
      if (matches(edges[e], edges[f], true)) partner = true;
      else if (matches(edges[e], edges[f], false)) {
        partner = true;
        ++report.flipped_edges;
        if (report.consistent && report.closed)
          report.problem = name(e) + " runs the same way as " + name(f) +
                           ": the two patches are oriented inconsistently";
        report.consistent = false;
      }
    }
    if (partner) continue;
    if (allow_z_planar_openings) {
      bool planar = true;
      for (const auto& q : edges[e]) planar = planar && std::abs(q.z - edges[e][0].z) <= tol;
      if (planar) {
        report.z_planar_openings.push_back({static_cast<int>(e / 4), static_cast<int>(e % 4)});
        continue;
      }
    }
    ++report.open_edges;
    if (report.consistent && report.closed)
      report.problem = name(e) + " meets no other patch edge" +
                       (allow_z_planar_openings ? " and does not lie in a plane z = const" : "") +
                       ": the patches do not close a volume";
    report.closed = false;
  }
  return report;
}

double cap_volume_term(const std::vector<scene::Patch>& patches,
                       const std::vector<PatchEdge>& openings) {
  std::vector<double> x, w;
  double term = 0;
  for (const PatchEdge& o : openings) {
    const scene::Patch& p = patches.at(o.patch);
    const PatchSurface surface(p);
    // x·y' − y·x' along a Bézier edge has degree 2·degree − 1.
    gauss_legendre(std::max(p.degree_u, p.degree_v) + 1, x, w);
    double integral = 0, z0 = 0;
    for (size_t i = 0; i < x.size(); ++i) {
      const double t = x[i];
      const double u = o.edge == 0 ? t : o.edge == 1 ? 1.0 : o.edge == 2 ? 1.0 - t : 0.0;
      const double v = o.edge == 0 ? 0.0 : o.edge == 1 ? t : o.edge == 2 ? 1.0 : 1.0 - t;
      const SurfacePoint s = surface.evaluate(u, v);
      const Vec3 d = o.edge == 0 ? s.du : o.edge == 1 ? s.dv : o.edge == 2 ? -s.du : -s.dv;
      integral += w[i] * (s.p.x * d.y - s.p.y * d.x);
      z0 = s.p.z;
    }
    term += -z0 / 3.0 * 0.5 * integral;
  }
  return term;
}

}  // namespace rpu::patch
