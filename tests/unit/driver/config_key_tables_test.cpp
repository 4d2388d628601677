// docs/scenes.md's, docs/studies.md's and docs/spectra.md's Domains tables against the key tables
// (mpi_driver/config/scene_fields.hpp, study_fields.hpp, spectrum_fields.hpp): every key a table
// reads is in the docs with its table's domain, and every key the docs list is read, by a table or
// by the hand-written readers named here.
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "mpi_driver/config/distribution_json.hpp"
#include "mpi_driver/config/scene_fields.hpp"
#include "mpi_driver/config/spectrum_fields.hpp"
#include "mpi_driver/config/study_fields.hpp"

namespace blockfrag {
namespace {

// What one docs file's Domains table is checked against: the key tables, the names that select a
// table (a ground motion's type: not keys, but quoted in the name cells), the keys a hand-written
// reader reads, and whether the rows of another file's keys (scenes.md's study rows) are skipped.
struct DocsCheck {
  std::string file;
  std::vector<KeyTable> tables;
  std::set<std::string> selectors;
  std::set<std::string> hand_read_keys;
  bool skip_study_rows = false;
};

DocsCheck scenes_check() {
  DocsCheck check{"scenes.md", scene_key_tables(), {}, {}, true};
  check.hand_read_keys = {"block.polygon", "seat", "contact.rocking_restitution"};
  for (const std::string_view type : ground_motion_types()) check.selectors.emplace(type);
  for (const std::string_view method : method_names.names) check.selectors.emplace(method);
  return check;
}

DocsCheck studies_check() {
  DocsCheck check{"studies.md", study_key_tables(), {}, {}, false};
  check.hand_read_keys = {"inputs.*.distribution"};
  for (const auto& names : {std::span<const std::string_view>(distribution_names),
                            std::span<const std::string_view>(im_type_names.names),
                            std::span<const std::string_view>(limit_state_kind_names.names)}) {
    for (const std::string_view name : names) check.selectors.emplace(name);
  }
  return check;
}

DocsCheck spectra_check() {
  DocsCheck check{"spectra.md", spectrum_key_tables(), {}, {}, false};
  for (const std::string_view name : spectrum_pulse_names.names) check.selectors.emplace(name);
  return check;
}

struct DocsRow {
  std::string name_cell;
  std::vector<std::string> keys;  // the name cell's `quoted` words
  std::string domain_cell;
};

std::string read_doc(const std::string& file) {
  std::ifstream in(std::string(BLOCKFRAG_SOURCE_DIR) + "/docs/" + file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A table row's cells; "\|" is a bar inside a cell.
std::vector<std::string> table_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '|' && line[i - 1] != '\\') {
      const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
      cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return cells;
}

std::vector<std::string> quoted_words(const std::string& cell) {
  std::vector<std::string> words;
  for (std::size_t open = cell.find('`'); open != std::string::npos;) {
    const std::size_t close = cell.find('`', open + 1);
    if (close == std::string::npos) break;
    words.push_back(cell.substr(open + 1, close - open - 1));
    open = cell.find('`', close + 1);
  }
  return words;
}

// The rows of the "## Domains" section's table.
std::vector<DocsRow> domain_rows(const std::string& doc) {
  std::vector<DocsRow> rows;
  std::istringstream lines(doc.substr(doc.find("\n## Domains") + 1));
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line) && line.rfind("## ", 0) != 0) {
    if (line.rfind("|", 0) != 0) continue;
    const auto cells = table_cells(line);
    if (cells.size() < 2 || cells[0] == "value" || cells[0].rfind("---", 0) == 0) continue;
    rows.push_back({cells[0], quoted_words(cells[0]), cells[1]});
  }
  return rows;
}

// A bound as the docs write it: digits, or a label ("pi/2") the domain names too.
bool same_bound(std::string_view text, double value, const char* label) {
  if (label) return text == label;
  const std::string digits(text);
  char* end = nullptr;
  const double parsed = std::strtod(digits.c_str(), &end);
  return end == digits.c_str() + digits.size() && parsed == value;
}

// A domain without an upper bound as the docs write it: ">= 0", "> 1".
bool docs_lower_bound_matches(const std::string& text, const Domain& domain) {
  const std::string sign = domain.low_inclusive ? ">= " : "> ";
  if (domain.high != std::numeric_limits<double>::infinity() || text.rfind(sign, 0) != 0) {
    return false;
  }
  const std::string rest = text.substr(sign.size());
  return same_bound(std::string_view(rest).substr(0, rest.find(' ')), domain.low, domain.low_label);
}

// Whether the docs' domain cell ("[1e-4, 1e4] m", "integer in [1, 1000]", "integer >= 0", "any
// positive finite value, kg") starts with the field's domain.
bool docs_domain_matches(std::string text, const FieldDescription& field) {
  const Domain& domain = *field.domain;
  const std::string integer_prefix = "integer ";
  const bool integer = text.rfind(integer_prefix, 0) == 0;
  if (integer != (field.kind == FieldKind::integer)) return false;
  if (integer) text = text.substr(integer_prefix.size());
  if (integer && text.rfind("in ", 0) == 0) text = text.substr(3);
  if (text.rfind(">", 0) == 0) return docs_lower_bound_matches(text, domain);
  if (text.rfind("any number", 0) == 0) {
    return domain.low == -std::numeric_limits<double>::infinity() &&
           domain.high == std::numeric_limits<double>::infinity();
  }
  if (text.rfind("any positive finite value", 0) == 0) {
    return domain.low == 0.0 && !domain.low_inclusive &&
           domain.high == std::numeric_limits<double>::infinity();
  }
  const std::size_t comma = text.find(", "), close = text.find_first_of("])");
  if (text.empty() || comma == std::string::npos || close == std::string::npos || close < comma) {
    return false;
  }
  return (text[0] == '[') == domain.low_inclusive && (text[0] == '[' || text[0] == '(') &&
         (text[close] == ']') == domain.high_inclusive &&
         same_bound(std::string_view(text).substr(1, comma - 1), domain.low, domain.low_label) &&
         same_bound(std::string_view(text).substr(comma + 2, close - comma - 2), domain.high,
                    domain.high_label);
}

// Whether the docs' domain cell starts as the field's kind of value: a domain, or the words that
// name a boolean, a string or a sign.
bool docs_cell_matches(const std::string& text, const FieldDescription& field) {
  switch (field.kind) {
    case FieldKind::boolean: return text.rfind("`true` or `false`", 0) == 0;
    case FieldKind::text: return text.rfind("a string", 0) == 0;
    case FieldKind::sign: return text.rfind("1 or -1", 0) == 0;
    case FieldKind::number:
    case FieldKind::numbers:
    case FieldKind::integer: return docs_domain_matches(text, field);
    case FieldKind::choice: break;
  }
  return false;
}

// What the docs' domain cell of a field's kind starts with.
std::string expected_cell(const FieldDescription& field) {
  switch (field.kind) {
    case FieldKind::boolean: return "`true` or `false`";
    case FieldKind::text: return "a string";
    case FieldKind::sign: return "1 or -1";
    case FieldKind::integer: return "its domain integer " + field.domain->rule();
    case FieldKind::number:
    case FieldKind::numbers: return "its domain " + field.domain->rule();
    case FieldKind::choice: break;
  }
  return "";
}

// The docs' problems with one table key: absent, or listed with another domain (a choice: one of
// its names not quoted anywhere).
void check_table_key(const std::string& doc, const std::vector<DocsRow>& rows,
                     const std::string& name, const FieldDescription& field,
                     std::vector<std::string>& problems) {
  if (field.kind == FieldKind::choice) {
    for (const std::string& choice : field.choices) {
      if (doc.find("`\"" + choice + "\"`") == std::string::npos) {
        problems.push_back(name + ": the docs do not name its choice \"" + choice + "\"");
      }
    }
    return;
  }
  bool named = false, matched = false;
  for (const DocsRow& row : rows) {
    for (const std::string& key : row.keys) {
      if (key != name) continue;
      named = true;
      matched = matched || docs_cell_matches(row.domain_cell, field);
    }
  }
  if (!named) problems.push_back(name + ": not in the docs' Domains table");
  if (named && !matched) {
    problems.push_back(name + ": no row of the docs' Domains table gives " + expected_cell(field));
  }
}

// Every disagreement between the docs' text and the key tables, one line each.
std::vector<std::string> disagreements(const std::string& doc, const DocsCheck& check) {
  const std::vector<DocsRow> rows = domain_rows(doc);
  std::vector<std::string> problems;
  std::set<std::string> table_keys = check.selectors;
  for (const KeyTable& table : check.tables) {
    for (const FieldDescription& field : table.fields) {
      const std::string name = table.prefix + field.key;
      table_keys.insert(name);
      check_table_key(doc, rows, name, field, problems);
    }
  }
  for (const DocsRow& row : rows) {
    const std::string& cell = row.name_cell;
    const bool study_row = cell.find("study") != std::string::npos ||
                           cell.find("Latin") != std::string::npos ||
                           cell.find("cloud") != std::string::npos;
    if (check.skip_study_rows && study_row) continue;
    for (const std::string& key : row.keys) {
      if (!table_keys.contains(key) && !check.hand_read_keys.contains(key)) {
        problems.push_back(key + ": in the docs' Domains table, read by no key table");
      }
    }
  }
  return problems;
}

std::vector<std::string> disagreements(const std::string& doc) {
  return disagreements(doc, scenes_check());
}

std::string read_scenes_doc() { return read_doc("scenes.md"); }

TEST(ConfigKeyTables, DocsDomainsTableAgreesWithTheSceneKeyTables) {
  const std::vector<std::string> problems = disagreements(read_scenes_doc());
  for (const std::string& problem : problems) ADD_FAILURE() << problem;
}

TEST(ConfigKeyTables, ATableKeyMissingFromTheDocsIsFound) {
  std::string doc = read_scenes_doc();
  const std::string row = "| `contact.restitution` | [0, 1] | |\n";
  const auto at = doc.find(row);
  ASSERT_NE(at, std::string::npos);
  doc.erase(at, row.size());
  EXPECT_EQ(disagreements(doc),
            std::vector<std::string>{"contact.restitution: not in the docs' Domains table"});
}

TEST(ConfigKeyTables, ADocsDomainOtherThanTheTablesIsFound) {
  std::string doc = read_scenes_doc();
  const std::string row = "| `g` | [0.01, 1000] m/s^2 |";
  const auto at = doc.find(row);
  ASSERT_NE(at, std::string::npos);
  doc.replace(at, row.size(), "| `g` | [0.01, 100] m/s^2 |");
  EXPECT_EQ(disagreements(doc),
            std::vector<std::string>{
                "g: no row of the docs' Domains table gives its domain must be in [0.01, 1000]"});
}

TEST(ConfigKeyTables, ADocsKeyNoReaderReadsIsFound) {
  std::string doc = read_scenes_doc();
  const std::string row = "| `initial.omega` |";
  const auto at = doc.find(row);
  ASSERT_NE(at, std::string::npos);
  doc.insert(at, "| `initial.phi` | [0, 1] rad | |\n");
  EXPECT_EQ(
      disagreements(doc),
      std::vector<std::string>{"initial.phi: in the docs' Domains table, read by no key table"});
}

TEST(ConfigKeyTables, DocsStudiesDomainsTableAgreesWithTheStudyKeyTables) {
  const std::vector<std::string> problems = disagreements(read_doc("studies.md"), studies_check());
  for (const std::string& problem : problems) ADD_FAILURE() << problem;
}

TEST(ConfigKeyTables, AStudyTableKeyMissingFromTheDocsIsFound) {
  std::string doc = read_doc("studies.md");
  const std::string row = "| `design.adaptive.pair_probability` | [0.01, 0.49] | default 0.128 |\n";
  const auto at = doc.find(row);
  ASSERT_NE(at, std::string::npos);
  doc.erase(at, row.size());
  EXPECT_EQ(
      disagreements(doc, studies_check()),
      std::vector<std::string>{"design.adaptive.pair_probability: not in the docs' Domains table"});
}

TEST(ConfigKeyTables, AStudyDocsDomainOtherThanTheTablesIsFound) {
  std::string doc = read_doc("studies.md");
  const std::string cell = "| `intensity_measure.damping` (`sa`) | [0, 1) |";
  const auto at = doc.find(cell);
  ASSERT_NE(at, std::string::npos);
  doc.replace(at, cell.size(), "| `intensity_measure.damping` (`sa`) | [0, 1] |");
  EXPECT_EQ(disagreements(doc, studies_check()),
            std::vector<std::string>{"intensity_measure.damping: no row of the docs' Domains "
                                     "table gives its domain must be in [0, 1)"});
}

// A boolean's, a sign's and a string's rows say what kind of value they take.
TEST(ConfigKeyTables, AStudyDocsKindOtherThanTheTablesIsFound) {
  std::string doc = read_doc("studies.md");
  for (const auto& [cell, wrong] :
       {std::pair<std::string, std::string>{"(`fixed`) | 1 or -1 |", "(`fixed`) | any number |"},
        {"(all but `overturning`) | `true` or `false` |", "(all but `overturning`) | 0 or 1 |"},
        {"| `design.adaptive.limit_state` | a string",
         "| `design.adaptive.limit_state` | a name"}}) {
    const auto at = doc.find(cell);
    ASSERT_NE(at, std::string::npos) << cell;
    doc.replace(at, cell.size(), wrong);
  }
  EXPECT_EQ(disagreements(doc, studies_check()),
            (std::vector<std::string>{
                "inputs.direction.value: no row of the docs' Domains table gives 1 or -1",
                "limit_states[].overturned_exceeds: no row of the docs' Domains table gives "
                "`true` or `false`",
                "design.adaptive.limit_state: no row of the docs' Domains table gives a string"}));
}

TEST(ConfigKeyTables, AStringKeyMissingFromTheDocsIsFound) {
  std::string doc = read_doc("scenes.md");
  const std::string row = "| a record's `file` |";
  const auto at = doc.find(row);
  ASSERT_NE(at, std::string::npos);
  doc.erase(at, doc.find('\n', at) + 1 - at);
  EXPECT_EQ(disagreements(doc), std::vector<std::string>{"file: not in the docs' Domains table"});
}

TEST(ConfigKeyTables, AStudyChoiceTheDocsDoNotNameIsFound) {
  std::string doc = read_doc("studies.md");
  for (std::size_t at = doc.find("`\"stripes\"`"); at != std::string::npos;
       at = doc.find("`\"stripes\"`")) {
    doc.replace(at, 11, "stripes");
  }
  EXPECT_EQ(disagreements(doc, studies_check()),
            std::vector<std::string>{
                "intensity_measure.scaling: the docs do not name its choice \"stripes\""});
}

TEST(ConfigKeyTables, AStudyDocsKeyNoReaderReadsIsFound) {
  std::string doc = read_doc("studies.md");
  const std::string row = "| `seed` |";
  const auto at = doc.find(row);
  ASSERT_NE(at, std::string::npos);
  doc.insert(at, "| `design.adaptive.batches` | integer in [1, 10] | |\n");
  EXPECT_EQ(disagreements(doc, studies_check()),
            std::vector<std::string>{
                "design.adaptive.batches: in the docs' Domains table, read by no key table"});
}

TEST(ConfigKeyTables, DocsSpectraDomainsTableAgreesWithTheSpectrumKeyTables) {
  const std::vector<std::string> problems = disagreements(read_doc("spectra.md"), spectra_check());
  for (const std::string& problem : problems) ADD_FAILURE() << problem;
}

TEST(ConfigKeyTables, ASpectrumTableKeyMissingFromTheDocsIsFound) {
  std::string doc = read_doc("spectra.md");
  const std::string row = "| `settle_allowance_tau` | [1, 1e6] (in 1/p) | default 200 |\n";
  const auto at = doc.find(row);
  ASSERT_NE(at, std::string::npos);
  doc.erase(at, row.size());
  EXPECT_EQ(disagreements(doc, spectra_check()),
            std::vector<std::string>{"settle_allowance_tau: not in the docs' Domains table"});
}

TEST(ConfigKeyTables, ASpectrumDocsDomainOtherThanTheTablesIsFound) {
  std::string doc = read_doc("spectra.md");
  const std::string cell = "| `pulse.n` (`makris_c`) | integer in [1, 1000] |";
  const auto at = doc.find(cell);
  ASSERT_NE(at, std::string::npos);
  doc.replace(at, cell.size(), "| `pulse.n` (`makris_c`) | [1, 1000] |");
  EXPECT_EQ(disagreements(doc, spectra_check()),
            std::vector<std::string>{"pulse.n: no row of the docs' Domains table gives its domain "
                                     "integer must be in [1, 1000]"});
}

TEST(ConfigKeyTables, ASpectrumChoiceTheDocsDoNotNameIsFound) {
  std::string doc = read_doc("spectra.md");
  for (std::size_t at = doc.find("`\"log\"`"); at != std::string::npos;
       at = doc.find("`\"log\"`")) {
    doc.replace(at, 7, "log");
  }
  EXPECT_EQ(disagreements(doc, spectra_check()),
            (std::vector<std::string>{
                "frequency_ratio.spacing: the docs do not name its choice \"log\"",
                "amplitude_ratio.spacing: the docs do not name its choice \"log\""}));
}

TEST(ConfigKeyTables, ASpectrumDocsKeyNoReaderReadsIsFound) {
  std::string doc = read_doc("spectra.md");
  const std::string row = "| `settle_allowance_tau` | [1, 1e6]";
  const auto at = doc.find(row);
  ASSERT_NE(at, std::string::npos);
  doc.insert(at, "| `bisection.min_iterations` | integer in [1, 200] | |\n");
  EXPECT_EQ(disagreements(doc, spectra_check()),
            std::vector<std::string>{
                "bisection.min_iterations: in the docs' Domains table, read by no key table"});
}

}  // namespace
}  // namespace blockfrag
