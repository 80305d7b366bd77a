// Reading a user's JSON file (scenes, sweep files) strictly and in linear time: one pass of
// nlohmann's SAX parser that builds the document, refuses duplicate keys, numbers too large for
// a double and nesting deeper than limits::kMaxJsonDepth, each naming its JSON path, and reports
// syntax errors by line and column without nlohmann's exception text.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace rpu::json_input {

// The document in `text`. Errors are rpu::Error with where = "<source>" or "<source>: <path>":
// "invalid JSON at line L, column C: <detail>", "duplicate key 'k'; each key may appear once",
// "not a finite number ...", "nested too deeply ...". `empty_problem` is the problem reported for
// a file of white space only.
nlohmann::json parse(const std::string& text, const std::string& source,
                     const std::string& empty_problem);

// What a JSON value is, for "got ..." in messages: null, true, a string, an empty array, an array
// of 3, an object, or a number's shortest text.
std::string describe(const nlohmann::json& j);

}  // namespace rpu::json_input
