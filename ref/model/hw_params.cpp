#include "model/hw_params.h"

#include <charconv>

#include <fmt/format.h>

#include "common/error.h"

namespace rpu::ref {
namespace {

// "name=value (gloss)|..." of hw_params.def's choices column.
std::vector<HwChoice> parse_choices(std::string_view text) {
  std::vector<HwChoice> out;
  while (!text.empty()) {
    const size_t bar = text.find('|');
    std::string_view item = text.substr(0, bar);
    text = bar == std::string_view::npos ? std::string_view() : text.substr(bar + 1);
    HwChoice c;
    const size_t eq = item.find('=');
    c.name = std::string(item.substr(0, eq));
    item = item.substr(eq + 1);
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), c.value);
    if (ec != std::errc())
      throw std::logic_error("hw_params.def: bad choices '" + std::string(item) + "'");
    item = item.substr(static_cast<size_t>(end - item.data()));
    if (item.starts_with(" (") && item.ends_with(")"))
      c.gloss = std::string(item.substr(2, item.size() - 3));
    out.push_back(std::move(c));
  }
  return out;
}

// A Markdown table cell: '|' escaped.
std::string cell(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

const std::vector<HwParamInfo>& hw_param_table() {
  static const std::vector<HwParamInfo> table = [] {
    std::vector<HwParamInfo> t;
#define RPU_HW_PARAM(field_, type_, key_, flag_, verilog_, symbol_, def_, kind_, lo_, hi_,       \
                     choices_, constraint_, what_, meaning_)                                     \
  t.push_back(HwParamInfo{.id = HwParamId::field_,                                               \
                          .field = #field_,                                                      \
                          .key = key_,                                                           \
                          .flag = flag_,                                                         \
                          .verilog = verilog_,                                                   \
                          .symbol = symbol_,                                                     \
                          .def = static_cast<int>(def_),                                         \
                          .kind = HwParamKind::kind_,                                            \
                          .min = lo_,                                                            \
                          .max = hi_,                                                            \
                          .choices = parse_choices(choices_),                                    \
                          .constraint = constraint_,                                             \
                          .what = what_,                                                         \
                          .meaning = meaning_,                                                   \
                          .get = [](const HwParams& p) { return static_cast<int>(p.field_); },   \
                          .set = [](HwParams& p, int v) { p.field_ = static_cast<type_>(v); }});
#include "model/hw_params.def"
#undef RPU_HW_PARAM
    return t;
  }();
  return table;
}

const HwParamInfo& hw_param(HwParamId id) { return hw_param_table()[static_cast<size_t>(id)]; }

const HwParamInfo* find_hw_param_key(std::string_view key) {
  for (const HwParamInfo& d : hw_param_table())
    if (d.key == key) return &d;
  return nullptr;
}

const HwParamInfo* find_hw_param_verilog(std::string_view name) {
  for (const HwParamInfo& d : hw_param_table())
    if (!d.verilog.empty() && d.verilog == name) return &d;
  return nullptr;
}

std::string hw_param_keys() {
  std::string s;
  for (const HwParamInfo& d : hw_param_table())
    s += fmt::format("{}{}", s.empty() ? "" : ", ", d.key);
  return s;
}

const HwChoice* HwParamInfo::choice(int v) const {
  for (const HwChoice& c : choices)
    if (c.value == v) return &c;
  return nullptr;
}

const HwChoice* HwParamInfo::choice(std::string_view name) const {
  for (const HwChoice& c : choices)
    if (c.name == name) return &c;
  return nullptr;
}

std::string HwParamInfo::choice_list() const {
  std::string s;
  for (size_t k = 0; k < choices.size(); ++k)
    s += fmt::format("{}{}", k == 0 ? "" : k + 1 == choices.size() ? " or " : ", ",
                     choices[k].name);
  return s;
}

bool HwParamInfo::legal(int v) const {
  switch (kind) {
    case HwParamKind::kRange: return v >= min && v <= max;
    case HwParamKind::kRangeOrOff: return choice(v) != nullptr || (v >= min && v <= max);
    case HwParamKind::kChoice: return choice(v) != nullptr;
  }
  return false;
}

void HwParamInfo::check(int v) const {
  if (legal(v)) return;
  if (kind == HwParamKind::kChoice)
    throw Error(std::string(flag), fmt::format("must be {}, got {}", choice_list(), v));
  throw Error(std::string(flag), fmt::format("{} must be in [{}, {}], got {}", what, min, max, v));
}

std::string HwParamInfo::text(int v) const {
  if (kind == HwParamKind::kChoice)
    if (const HwChoice* c = choice(v)) return c->name;
  return std::to_string(v);
}

std::string HwParamInfo::describe(int v) const {
  const HwChoice* c = choice(v);
  if (!c) return std::to_string(v);
  return c->gloss.empty() ? c->name : c->name + " (" + c->gloss + ")";
}

std::string HwParamInfo::range_text() const {
  std::string s;
  if (kind == HwParamKind::kChoice) {
    for (const HwChoice& c : choices) s += fmt::format("{}{}", s.empty() ? "" : ", ", c.name);
  } else {
    for (const HwChoice& c : choices) s += fmt::format("{}, ", c.value);
    s += fmt::format("{}–{}", min, max);
  }
  if (!constraint.empty()) s += fmt::format(", {}", constraint);
  return s;
}

std::string HwParamInfo::default_text() const {
  const HwChoice* c = choice(def);
  if (!c) return std::to_string(def);
  return kind == HwParamKind::kChoice ? c->name : fmt::format("{} ({})", def, c->name);
}

void HwParams::validate() const {
  for (const HwParamInfo& d : hw_param_table()) d.check(d.get(*this));
  // The combinations.
  if (n % n1 != 0)
    throw Error("--n", fmt::format("n = {} is not a multiple of n1 = {} (K = n/n1 steps)", n, n1));
  // The surface CORDIC runs AW micro-rotations on surf_cordic_w() = LW + 6 bits; it takes at
  // most its width + 4 stages (rpu_cordic.h).
  if (angle_w > surf_cordic_w() + 4)
    throw Error("--angle-w", fmt::format("angle_w = {} needs more CORDIC stages than a {}-bit "
                                         "CORDIC takes (surf_w = {}: at most {})", angle_w,
                                         surf_cordic_w(), surf_w, surf_cordic_w() + 4));
  // The widest intermediate products must fit 126 bits (the model's __int128 and a sane RTL).
  const int alpha_product = 2 * diff_w() + 3 + inv_w + 1;  // ((A - p1)·d)·m
  if (alpha_product > 126)
    throw Error("--coord-w", fmt::format("coord_w = {} with inv_w = {} needs a {}-bit product "
                                         "(limit 126)", coord_w, inv_w, alpha_product));
  const int edge_product = (coord_w + 5) + (edge_w() + 15) + 2;  // q·E(i)
  if (edge_product > 126)
    throw Error("--edge-frac", fmt::format("edge_frac = {} with coord_w = {} needs a {}-bit "
                                           "product (limit 126)", edge_frac, coord_w, edge_product));
  const int weight_product = 2 * coord_w + 3 + t_frac;  // L²·w in the guide unit
  if (weight_product > 126)
    throw Error("--t-frac", fmt::format("t_frac = {} with coord_w = {} needs a {}-bit product "
                                        "L²·w (limit 126)", t_frac, coord_w, weight_product));
}

std::string HwParams::describe() const {
  std::string s;
  for (const HwParamInfo& d : hw_param_table()) {
    s += fmt::format("{:<10} = {}\n", d.key, d.describe(d.get(*this)));
    if (d.id == HwParamId::n1)  // what n and n1 make
      s += fmt::format("{:<10} = {}\n{:<10} = {} sub-intervals, {} candidate points ({} new after "
                       "the first step)\n", "K", K(), "per step", J(), J() + 1, J() - 1);
    if (d.id == HwParamId::surf_n1_first) {  // the surfaces' schedule it makes
      std::string bits;
      for (int k = 1; k <= surface_steps(); ++k) bits += fmt::format("{}{}", k > 1 ? "," : "", surface_step_bits(k));
      s += fmt::format("{:<10} = {} (bits per step), {} indicator evaluations per work item\n",
                       "surf steps", bits, surface_evaluations());
    }
  }
  return s;
}

std::string HwParams::summary() const {
  std::string s;
  for (const HwParamInfo& d : hw_param_table())
    s += fmt::format("{}{} {}", s.empty() ? "" : " ", d.key, d.text(d.get(*this)));
  return s;
}

HwParams hw_params_from_verilog(std::initializer_list<std::pair<std::string_view, int>> values) {
  HwParams p;
  for (const auto& [name, value] : values) {
    const HwParamInfo* d = find_hw_param_verilog(name);
    if (!d)
      throw Error(std::string(name), "no hardware parameter has this Verilog name (hw_params.def)");
    d->set(p, value);
  }
  return p;
}

std::string hw_params_markdown() {
  std::string s = "| name | flag | default | range | meaning |\n|---|---|---|---|---|\n";
  for (const HwParamInfo& d : hw_param_table())
    s += fmt::format("| {} | `{}` | {} | {} | {} |\n", d.symbol, d.flag, d.default_text(),
                     cell(d.range_text()), cell(d.meaning));
  return s;
}

std::string hw_params_readme_rows() {
  std::string s;
  for (const HwParamInfo& d : hw_param_table())
    s += fmt::format("| {} | `{}` | {} | {} |\n", d.key, d.flag, d.default_text(), cell(d.meaning));
  return s;
}

}  // namespace rpu::ref
