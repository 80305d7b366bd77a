#include "common/json_input.h"

#include <algorithm>
#include <optional>
#include <string_view>
#include <vector>

#include "common/error.h"
#include "common/limits.h"

namespace rpu::json_input {
namespace {

using Json = nlohmann::json;

}  // namespace

std::string describe(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return j.get<bool>() ? "true" : "false";
    case Json::value_t::string: return "a string";
    case Json::value_t::object: return "an object";
    case Json::value_t::array:
      return j.empty() ? "an empty array" : "an array of " + std::to_string(j.size());
    default: return j.dump();  // a number: its shortest text
  }
}

namespace {

// Builds the document in one pass of nlohmann's SAX parser (linear in the file size), tracking
// the JSON path of the value being read so that errors found while parsing (duplicate keys,
// number overflow, nesting too deep) can name it. (nlohmann's callback parser re-scans the parent
// container at the end of every object: quadratic in the number of objects in an array.)
class StrictSax {
 public:
  explicit StrictSax(const std::string& source) : source_(source) {}

  // The parsed document; valid when sax_parse returned true.
  Json take() { return std::move(root_); }
  // The error that stopped the parse (when a handler returned false), if any.
  const std::optional<Error>& error() const { return error_; }

  bool null() { return value(Json()); }
  bool boolean(bool v) { return value(Json(v)); }
  bool number_integer(Json::number_integer_t v) { return value(Json(v)); }
  bool number_unsigned(Json::number_unsigned_t v) { return value(Json(v)); }
  bool number_float(Json::number_float_t v, const std::string&) { return value(Json(v)); }
  bool string(std::string& v) { return value(Json(std::move(v))); }
  bool binary(Json::binary_t& v) { return value(Json::binary(std::move(v))); }

  bool start_object(std::size_t) { return open(Json::object(), false); }
  bool start_array(std::size_t) { return open(Json::array(), true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(std::string& k) {
    Frame& f = stack_.back();
    if (f.container->contains(k))
      return fail(path(stack_.size() - 1), "duplicate key '" + k + "'; each key may appear once");
    f.key = std::move(k);
    return true;
  }

  bool parse_error(std::size_t byte, const std::string&, const nlohmann::detail::exception& e) {
    if (e.id == 406)  // a number literal too large for a double (e.g. 1e999)
      return fail(path(stack_.size()),
                  "not a finite number (it overflows a double); expected a finite number");
    syntax_error_byte_ = byte;
    syntax_error_ = e.what();
    return false;
  }

  // Set when the parser stopped at a syntax error: its byte offset and nlohmann's message.
  std::optional<std::size_t> syntax_error_byte() const { return syntax_error_byte_; }
  const std::string& syntax_error() const { return syntax_error_; }

 private:
  struct Frame {
    Json* container;  // the open array or object (inside root_)
    bool array;
    std::size_t next_index = 0;  // arrays: index of the element being read
    std::string key;             // objects: the last key read
  };

  // Path of the value inside the first `depth` open containers ("" is the top level).
  std::string path(std::size_t depth) const {
    std::string p;
    for (std::size_t i = 0; i < depth; ++i) {
      const Frame& f = stack_[i];
      if (f.array) p.append("[").append(std::to_string(f.next_index)).append("]");
      else p.append(p.empty() ? "" : ".").append(f.key);
    }
    return p;
  }

  bool fail(const std::string& path, const std::string& problem) {
    error_.emplace(path.empty() ? source_ : source_ + ": " + path, problem);
    return false;
  }

  // Stores `v` where the parser is (the top level, the next array element or the last key) and
  // returns it.
  Json* place(Json&& v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Frame& f = stack_.back();
    if (f.array) {
      f.container->push_back(std::move(v));
      ++f.next_index;
      return &f.container->back();
    }
    return &((*f.container)[f.key] = std::move(v));
  }

  bool value(Json&& v) {
    place(std::move(v));
    return true;
  }

  bool open(Json&& empty, bool array) {
    if (stack_.size() >= static_cast<std::size_t>(limits::kMaxJsonDepth))
      return fail(path(stack_.size()),
                  "nested too deeply: at most " + std::to_string(limits::kMaxJsonDepth) +
                      " levels of arrays and objects are allowed");
    // Arrays count their elements when they are closed, so the path of an open array's element
    // is its index; the index advances in place() when the element is stored.
    Json* c = place(std::move(empty));
    if (!stack_.empty() && stack_.back().array) --stack_.back().next_index;
    stack_.push_back({c, array, 0, {}});
    return true;
  }

  bool close() {
    stack_.pop_back();
    if (!stack_.empty() && stack_.back().array) ++stack_.back().next_index;
    return true;
  }

  const std::string& source_;
  Json root_;
  std::vector<Frame> stack_;  // open containers, outermost first
  std::optional<Error> error_;
  std::optional<std::size_t> syntax_error_byte_;
  std::string syntax_error_;
};

// 1-based line and column of the 1-based byte offset `byte` in `text`.
std::string line_column(const std::string& text, size_t byte) {
  const size_t at = std::min(byte > 0 ? byte - 1 : 0, text.size());
  const size_t line = 1 + std::count(text.begin(), text.begin() + at, '\n');
  const size_t nl = text.rfind('\n', at == 0 ? std::string::npos : at - 1);
  const size_t column = (at == 0 || nl == std::string::npos) ? at + 1 : at - nl;
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's message without its "[json.exception.parse_error.N] parse error at line L,
// column C: " prefix (the caller says where, in the file's own lines and columns).
std::string parse_error_detail(const std::string& what) {
  std::string detail = what;
  if (detail.starts_with("[json.exception.")) {
    const size_t close = detail.find("] ");
    detail = close == std::string::npos ? std::string() : detail.substr(close + 2);
  }
  for (const std::string_view prefix : {"parse error at ", "parse error: ", "parse error "}) {
    if (!detail.starts_with(prefix)) continue;
    const size_t colon = detail.find(": ", detail.find("column"));
    detail = colon == std::string::npos ? detail.substr(prefix.size()) : detail.substr(colon + 2);
    break;
  }
  return detail.empty() ? "syntax error" : detail;
}

}  // namespace

Json parse(const std::string& text, const std::string& source, const std::string& empty_problem) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw Error(source, empty_problem);
  StrictSax sax(source);
  if (Json::sax_parse(text, &sax)) return sax.take();
  if (sax.error()) throw *sax.error();
  if (sax.syntax_error_byte())
    throw Error(source, "invalid JSON at " + line_column(text, *sax.syntax_error_byte()) + ": " +
                            parse_error_detail(sax.syntax_error()));
  throw Error(source, "invalid JSON");
}

}  // namespace rpu::json_input
