// docs/scene-format.md against the scene reader: the keys documented for every object are the
// keys the reader accepts (scene/scene_keys.h, the table the reader takes its key lists from),
// and every JSON example in the document is a valid scene.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "scene/scene_keys.h"

namespace rpu::scene {
namespace {

constexpr const char* kDoc = "docs/scene-format.md";
constexpr const char* kTableHeader = "| key | type | range | default | unit | source |";

std::vector<std::string> doc_lines() {
  std::ifstream in(std::string(RPU_SOURCE_DIR) + "/" + kDoc);
  if (!in) throw std::runtime_error(std::string("cannot read ") + kDoc);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::string without_backticks(std::string s) {
  std::erase(s, '`');
  return trim(s);
}

// The cells of a table row "| a | b |"; "\|" is a pipe inside a cell (as in "\|e\|").
std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  const std::string t = trim(row);
  if (t.size() < 2 || t.front() != '|' || t.back() != '|') return out;
  std::string cell;
  for (size_t i = 1; i + 1 < t.size(); ++i) {
    if (t[i] == '\\' && t[i + 1] == '|') {
      cell += '|';
      ++i;
    } else if (t[i] == '|') {
      out.push_back(trim(cell));
      cell.clear();
    } else {
      cell += t[i];
    }
  }
  out.push_back(trim(cell));
  return out;
}

// One "### " section of the document: its object path (the heading without backticks), the keys
// of its table, and how many ```json examples it holds.
struct Section {
  std::string path;
  size_t line = 0;  // 1-based line of the heading
  bool has_table = false;
  std::vector<std::string> keys;
  int examples = 0;
};

// Reads every "### " section. Problems with the document's form go to `problems`.
std::vector<Section> doc_sections(const std::vector<std::string>& lines,
                                  std::vector<std::string>& problems) {
  std::vector<Section> out;
  Section* cur = nullptr;
  bool in_code = false;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    const std::string where = std::string(kDoc) + ":" + std::to_string(i + 1);
    if (l.starts_with("```")) {
      if (!in_code && cur && trim(l) == "```json") ++cur->examples;
      in_code = !in_code;
      continue;
    }
    if (in_code) continue;
    if (l.starts_with("#")) {  // any heading ends the current section
      cur = nullptr;
      if (l.starts_with("### ")) {
        cur = &out.emplace_back();
        cur->path = without_backticks(l.substr(4));
        cur->line = i + 1;
      }
      continue;
    }
    if (!cur || !trim(l).starts_with("|") || cur->has_table) continue;
    // The section's table: the header, the separator, then one row per key.
    if (cells(l) != cells(kTableHeader)) {
      problems.push_back(where + ": the table of '" + cur->path + "' must have the header " +
                         kTableHeader);
      cur->has_table = true;
      continue;
    }
    cur->has_table = true;
    if (i + 1 >= lines.size() || !trim(lines[i + 1]).starts_with("|---"))
      problems.push_back(where + ": the table header of '" + cur->path +
                         "' must be followed by a |---| separator row");
    size_t r = i + 2;  // past the separator
    for (; r < lines.size() && trim(lines[r]).starts_with("|"); ++r) {
      const std::vector<std::string> c = cells(lines[r]);
      const std::string row_where = std::string(kDoc) + ":" + std::to_string(r + 1);
      if (c.size() != 6) {
        problems.push_back(row_where + ": expected 6 cells, got " + std::to_string(c.size()));
        continue;
      }
      const std::string key = without_backticks(c[0]);
      if (key.empty() || key.find(' ') != std::string::npos || c[0].front() != '`')
        problems.push_back(row_where + ": the key cell must be one key in backticks, got '" +
                           c[0] + "'");
      else
        cur->keys.push_back(key);
    }
    i = r - 1;
  }
  return out;
}

// "(path, key)" for printing.
std::string describe(const std::set<std::pair<std::string, std::string>>& pairs) {
  std::string s;
  for (const auto& [path, key] : pairs) s += "\n  " + path + ": " + key;
  return s.empty() ? "\n  (none)" : s;
}

TEST(SceneFormatDoc, KeysMatchTheSceneReader) {
  std::vector<std::string> problems;
  const std::vector<Section> sections = doc_sections(doc_lines(), problems);

  std::set<std::pair<std::string, std::string>> doc, reader;
  std::set<std::string> headings;
  for (const Section& s : sections) {
    if (!headings.insert(s.path).second)
      problems.push_back(std::string(kDoc) + ":" + std::to_string(s.line) + ": heading '" +
                         s.path + "' appears twice");
    if (!s.has_table)
      problems.push_back(std::string(kDoc) + ":" + std::to_string(s.line) + ": '" + s.path +
                         "' has no key table");
    for (const std::string& k : s.keys)
      if (!doc.insert({s.path, k}).second)
        problems.push_back(std::string(kDoc) + ":" + std::to_string(s.line) + ": '" + s.path +
                           "' lists key '" + k + "' twice");
  }
  for (const ObjectKeys& o : kSceneKeys)
    for (const std::string_view k : o.keys) reader.insert({std::string(o.path), std::string(k)});

  std::set<std::pair<std::string, std::string>> doc_only, reader_only;
  for (const auto& p : doc)
    if (!reader.contains(p)) doc_only.insert(p);
  for (const auto& p : reader)
    if (!doc.contains(p)) reader_only.insert(p);

  EXPECT_TRUE(problems.empty()) << [&] {
    std::string s;
    for (const std::string& p : problems) s += "\n  " + p;
    return s;
  }();
  EXPECT_TRUE(doc_only.empty() && reader_only.empty())
      << "keys in " << kDoc << " only:" << describe(doc_only)
      << "\nkeys the scene reader accepts (ref/scene/scene_keys.h) but " << kDoc
      << " does not document:" << describe(reader_only);
}

TEST(SceneFormatDoc, EveryObjectHasAnExample) {
  std::vector<std::string> problems;
  for (const Section& s : doc_sections(doc_lines(), problems))
    EXPECT_GE(s.examples, 1) << kDoc << ":" << s.line << ": '" << s.path
                             << "' has no ```json example";
}

TEST(SceneFormatDoc, EveryJsonExampleIsAValidScene) {
  const std::vector<std::string> lines = doc_lines();
  int examples = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (trim(lines[i]) != "```json") continue;
    std::string text;
    size_t end = i + 1;
    for (; end < lines.size() && !lines[end].starts_with("```"); ++end) text += lines[end] + "\n";
    ASSERT_LT(end, lines.size()) << kDoc << ":" << i + 1 << ": unterminated ```json block";
    const std::string source = std::string(kDoc) + ":" + std::to_string(i + 1);
    ++examples;
    try {
      const Scene scene = parse_scene(text, source);
      (void)compile_scene(scene);  // camera frame and segments, as `rpu render` builds them
    } catch (const Error& e) {
      ADD_FAILURE() << "example rejected: " << e.what();
    }
    i = end;
  }
  EXPECT_GE(examples, static_cast<int>(std::size(kSceneKeys)));
}

// The document stands alone: no reference to specification files outside the repository.
TEST(SceneFormatDoc, CitesNoFileOutsideTheRepository) {
  const std::vector<std::string> lines = doc_lines();
  for (size_t i = 0; i < lines.size(); ++i)
    for (const char* outside : {"SCENE.md", "ALGORITHM.md", "ARCHITECTURE.md", "../shared"})
      EXPECT_EQ(lines[i].find(outside), std::string::npos)
          << kDoc << ":" << i + 1 << " cites " << outside;
}

}  // namespace
}  // namespace rpu::scene
