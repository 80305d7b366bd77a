#include "hw_flags.h"

#include <charconv>

#include "common/error.h"

namespace rpu::app {

using ref::HwParamInfo;
using ref::HwParamKind;

HwFlags::HwFlags() {
  for (const HwParamInfo& d : ref::hw_param_table()) {
    value_.push_back(d.def);
    // Choices and ranges with a named value are read as text: a name or (ranges) an integer.
    text_.push_back(d.kind != HwParamKind::kRange ? d.text(d.def) : std::string());
  }
}

void HwFlags::add_to(CLI::App& app) {
  const auto& table = ref::hw_param_table();
  for (size_t k = 0; k < table.size(); ++k) {
    const HwParamInfo& d = table[k];
    const std::string flag(d.flag), help(d.meaning);
    if (d.kind != HwParamKind::kRange)
      app.add_option(flag, text_[k], help)->capture_default_str();
    else
      app.add_option(flag, value_[k], help)->capture_default_str();
  }
}

ref::HwParams HwFlags::params() const {
  ref::HwParams p;
  const auto& table = ref::hw_param_table();
  for (size_t k = 0; k < table.size(); ++k) {
    const HwParamInfo& d = table[k];
    if (d.kind == HwParamKind::kRange) {
      d.set(p, value_[k]);
      continue;
    }
    if (const ref::HwChoice* c = d.choice(text_[k])) {
      d.set(p, c->value);
      continue;
    }
    int v = 0;
    const char* b = text_[k].data();
    const char* e = b + text_[k].size();
    const auto [end, ec] = std::from_chars(b, e, v);
    if (d.kind == HwParamKind::kChoice || ec != std::errc() || end != e || b == e)
      throw Error(std::string(d.flag), "must be " + d.choice_list() +
                                           (d.kind == HwParamKind::kChoice ? "" : " or an integer") +
                                           ", got '" + text_[k] + "'");
    d.set(p, v);  // validate() judges the range
  }
  p.validate();
  return p;
}

std::vector<std::string> HwFlags::given(const CLI::App& app) const {
  std::vector<std::string> out;
  for (const HwParamInfo& d : ref::hw_param_table())
    if (app.count(std::string(d.flag)) > 0) out.emplace_back(d.flag);
  return out;
}

}  // namespace rpu::app
