#include "stream_file.h"

#include <cstring>
#include <fstream>
#include <string_view>

#include <fmt/format.h>

#include "common/error.h"

namespace rpu::sim {

namespace {

constexpr std::uint32_t kJobMagic = 0x52505531;     // "RPU1"
constexpr std::uint32_t kStreamMagic = 0x52505532;  // "RPU2"
constexpr std::uint32_t kShardMagic = 0x52505533;   // "RPU3"
constexpr std::uint32_t kShardVersion = 1;

class Writer {
 public:
  explicit Writer(const std::string& path) : path_(path), out_(path, std::ios::binary) {
    if (!out_) throw Error(path, "cannot open for writing");
  }
  void u32(std::uint32_t v) { out_.write(reinterpret_cast<const char*>(&v), 4); }
  void u64(std::uint64_t v) { out_.write(reinterpret_cast<const char*>(&v), 8); }
  void i128v(i128 v) {
    u64(static_cast<std::uint64_t>(static_cast<u128>(v)));
    u64(static_cast<std::uint64_t>(static_cast<u128>(v) >> 64));
  }
  void f64(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, 8);
    u64(b);
  }
  void bits(const Bits& b) {
    u32(static_cast<std::uint32_t>(b.width()));
    for (auto w : b.words()) u32(w);
  }
  void text(std::string_view s) {
    u32(static_cast<std::uint32_t>(s.size()));
    out_.write(s.data(), static_cast<std::streamsize>(s.size()));
  }
  void close() {
    out_.close();
    if (!out_) throw Error(path_, "write failed");
  }

 private:
  std::string path_;
  std::ofstream out_;
};

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) throw Error(path, "cannot open for reading");
  }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    get(&v, 4);
    return v;
  }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    get(&v, 8);
    return v;
  }
  i128 i128v() {
    const u128 lo = u64();
    const u128 hi = u64();
    return static_cast<i128>(lo | (hi << 64));
  }
  double f64() {
    const std::uint64_t b = u64();
    double v;
    std::memcpy(&v, &b, 8);
    return v;
  }
  Bits bits() {
    const std::uint32_t w = u32();
    if (w > 65536) throw Error(path_, "corrupt bit vector width");
    Bits b(static_cast<int>(w));
    for (auto& x : b.words()) x = u32();
    return b;
  }
  std::string text() {
    const std::uint32_t n = u32();
    if (n > 256) throw Error(path_, "corrupt string length");
    std::string s(n, '\0');
    get(s.data(), n);
    return s;
  }
  std::uint32_t count(std::uint32_t max) {
    const std::uint32_t n = u32();
    if (n > max) throw Error(path_, "corrupt record count");
    return n;
  }

 private:
  void get(void* p, std::size_t n) {
    in_.read(static_cast<char*>(p), static_cast<std::streamsize>(n));
    if (!in_) throw Error(path_, "truncated file");
  }
  std::string path_;
  std::ifstream in_;
};

// The hardware parameters: the format version, their count, then each as its key (the reader
// checks it is its own table's, in order) and its value as an int, in the table's order
// (ref/model/hw_params.def).
void put_params(Writer& w, const ref::HwParams& p) {
  w.u32(kJobFileVersion);
  const auto& table = ref::hw_param_table();
  w.u32(static_cast<std::uint32_t>(table.size()));
  for (const ref::HwParamInfo& d : table) {
    w.text(d.key);
    w.u32(static_cast<std::uint32_t>(d.get(p)));
  }
}
ref::HwParams get_params(Reader& r, const std::string& path) {
  const std::uint32_t version = r.u32();
  if (version != kJobFileVersion)
    throw Error(path, fmt::format("job file format {}, this program reads format {} (written by "
                                  "another version of rpu)", version, kJobFileVersion));
  const auto& table = ref::hw_param_table();
  const std::uint32_t count = r.u32();
  if (count != table.size())
    throw Error(path, fmt::format("the job file has {} hardware parameters, this program {} "
                                  "(written by another version of rpu)", count, table.size()));
  ref::HwParams p;
  for (const ref::HwParamInfo& d : table) {
    const std::string key = r.text();
    if (key != d.key)
      throw Error(path, fmt::format("the job file has hardware parameter '{}' where this program "
                                    "has '{}' (written by another version of rpu)", key, d.key));
    d.set(p, static_cast<int>(r.u32()));
  }
  return p;
}

}  // namespace

void write_job(const std::string& path, const FrameSchedule& f) {
  Writer w(path);
  w.u32(kJobMagic);
  put_params(w, f.params);
  w.u32(static_cast<std::uint32_t>(f.width));
  w.u32(static_cast<std::uint32_t>(f.height));
  w.bits(f.camera);
  w.u32(static_cast<std::uint32_t>(f.segments.size()));
  for (const Bits& b : f.segments) w.bits(b);
  w.u32(static_cast<std::uint32_t>(f.surfaces.size()));
  for (const Bits& b : f.surfaces) w.bits(b);
  w.u32(static_cast<std::uint32_t>(f.items.size()));
  for (const WorkItem& it : f.items) {
    w.u32(it.id);
    w.u32(static_cast<std::uint32_t>(it.i));
    w.u32(static_cast<std::uint32_t>(it.j));
    w.u32(it.seg);
    w.u32((it.last ? 1u : 0u) | (it.texture ? 2u : 0u) | (it.surface ? 4u : 0u) |
          static_cast<std::uint32_t>(it.piece) << 3);
  }
  w.u32(static_cast<std::uint32_t>(f.expected_pixels.size()));
  w.close();
}

FrameSchedule read_job(const std::string& path) {
  Reader r(path);
  if (r.u32() != kJobMagic) throw Error(path, "not an rpu co-simulation job file");
  FrameSchedule f;
  f.params = get_params(r, path);
  f.width = static_cast<int>(r.u32());
  f.height = static_cast<int>(r.u32());
  f.camera = r.bits();
  const std::uint32_t nseg = r.count(1u << 16);
  for (std::uint32_t k = 0; k < nseg; ++k) f.segments.push_back(r.bits());
  const std::uint32_t nsurf = r.count(1u << 16);
  for (std::uint32_t k = 0; k < nsurf; ++k) f.surfaces.push_back(r.bits());
  const std::uint32_t n = r.count(1u << 30);
  f.items.resize(n);
  for (WorkItem& it : f.items) {
    it.id = r.u32();
    it.i = static_cast<int>(r.u32());
    it.j = static_cast<int>(r.u32());
    it.seg = r.u32();
    const std::uint32_t flags = r.u32();
    it.last = flags & 1u;
    it.texture = flags & 2u;
    it.surface = flags & 4u;
    it.piece = static_cast<int>(flags >> 3 & 3u);
    f.count(it);
  }
  // The pixel count sizes the pixel stream (its values are not needed by the harness).
  f.expected_pixels.resize(r.count(1u << 30));
  return f;
}

namespace {

void put_streams(Writer& w, const StreamRecord& s) {
  const CosimStats& st = s.stats;
  for (std::uint64_t v : {st.cycles, st.load_cycles, st.items, st.curve_items, st.texture_items,
                          st.surface_items, st.pixels, st.hits, st.latency_cycles,
                          st.stall_cycles})
    w.u64(v);
  w.f64(st.sim_seconds);
  w.u32(st.timed_out ? 1 : 0);
  w.u32(static_cast<std::uint32_t>(s.results.size()));
  for (const ItemResult& r : s.results) {
    w.u32(r.id);
    w.u32(static_cast<std::uint32_t>(r.i));
    w.u32(static_cast<std::uint32_t>(r.j));
    w.u32(r.seg);
    w.u32((r.last ? 1u : 0u) | (r.texture ? 2u : 0u) | (r.pred1 ? 4u : 0u) | (r.hit ? 8u : 0u) |
          (r.overflow ? 16u : 0u) | (r.surface ? 32u : 0u) |
          static_cast<std::uint32_t>(r.piece) << 6 | static_cast<std::uint32_t>(r.pieces) << 8);
    w.u32(r.primitive);
    w.i128v(r.depth);
    w.u64(r.tau);
    w.i128v(r.t);
    for (int c = 0; c < 3; ++c) w.i128v(r.X[c]);
  }
  w.u32(static_cast<std::uint32_t>(s.pixels.size()));
  for (const PixelResult& p : s.pixels) {
    w.u32(static_cast<std::uint32_t>(p.i));
    w.u32(static_cast<std::uint32_t>(p.j));
    w.u32(p.hit ? 1 : 0);
    w.i128v(p.depth);
    w.u32(p.primitive);
  }
}

StreamRecord get_streams(Reader& r) {
  StreamRecord s;
  CosimStats& st = s.stats;
  for (std::uint64_t* v : {&st.cycles, &st.load_cycles, &st.items, &st.curve_items,
                           &st.texture_items, &st.surface_items, &st.pixels, &st.hits, &st.latency_cycles,
                           &st.stall_cycles})
    *v = r.u64();
  st.sim_seconds = r.f64();
  st.timed_out = r.u32() != 0;
  s.results.resize(r.count(1u << 30));
  for (ItemResult& x : s.results) {
    x.id = r.u32();
    x.i = static_cast<int>(r.u32());
    x.j = static_cast<int>(r.u32());
    x.seg = r.u32();
    const std::uint32_t fl = r.u32();
    x.last = fl & 1u;
    x.texture = fl & 2u;
    x.pred1 = fl & 4u;
    x.hit = fl & 8u;
    x.overflow = fl & 16u;
    x.surface = fl & 32u;
    x.piece = static_cast<int>(fl >> 6 & 3u);
    x.pieces = static_cast<int>(fl >> 8 & 3u);
    x.primitive = r.u32();
    x.depth = r.i128v();
    x.tau = r.u64();
    x.t = r.i128v();
    for (auto& c : x.X) c = r.i128v();
  }
  s.pixels.resize(r.count(1u << 30));
  for (PixelResult& p : s.pixels) {
    p.i = static_cast<int>(r.u32());
    p.j = static_cast<int>(r.u32());
    p.hit = r.u32() != 0;
    p.depth = r.i128v();
    p.primitive = r.u32();
  }
  return s;
}

}  // namespace

void write_streams(const std::string& path, const StreamRecord& s) {
  Writer w(path);
  w.u32(kStreamMagic);
  put_streams(w, s);
  w.close();
}

StreamRecord read_streams(const std::string& path) {
  Reader r(path);
  if (r.u32() != kStreamMagic) throw Error(path, "not an rpu co-simulation stream file");
  return get_streams(r);
}

void write_shard(const std::string& path, const ShardRecord& s) {
  Writer w(path);
  w.u32(kShardMagic);
  w.u32(kShardVersion);
  w.u64(s.digest);
  w.u32(static_cast<std::uint32_t>(s.share.index));
  w.u32(static_cast<std::uint32_t>(s.share.count));
  for (std::size_t v : {s.share.first_item, s.share.end_item, s.share.first_pixel,
                        s.share.end_pixel})
    w.u64(v);
  w.text(s.config);
  put_streams(w, s.streams);
  w.close();
}

ShardRecord read_shard(const std::string& path) {
  Reader r(path);
  if (r.u32() != kShardMagic)
    throw Error(path, "not an rpu shard file (written by `rpu render --backend rtl --shard I/N`)");
  const std::uint32_t version = r.u32();
  if (version != kShardVersion)
    throw Error(path, fmt::format("shard file format {}, this program reads format {} (written by "
                                  "another version of rpu)", version, kShardVersion));
  ShardRecord s;
  s.digest = r.u64();
  s.share.index = static_cast<int>(r.u32());
  s.share.count = static_cast<int>(r.u32());
  for (std::size_t* v : {&s.share.first_item, &s.share.end_item, &s.share.first_pixel,
                         &s.share.end_pixel})
    *v = static_cast<std::size_t>(r.u64());
  s.config = r.text();
  s.streams = get_streams(r);
  return s;
}

}  // namespace rpu::sim
