// The config reader: every error names its JSON pointer and rule, all errors come together, typos
// get a hint, malformed text gets line:column. Expected messages are written out by hand from the
// documented format, and positions are counted by hand in the test texts.
#include "mpi_driver/config/config_reader.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/input_file.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

// Every message the reading of `document` by `read` produced (empty when it was accepted).
template <class Read>
std::vector<std::string> messages_of(const json& document, Read read) {
  ConfigErrors errors("test.json");
  ObjectReader root(document, JsonPointer{}, errors);
  read(root);
  root.finish();
  try {
    errors.throw_if_any();
  } catch (const ConfigError& error) {
    return error.messages();
  }
  return {};
}

std::string parse_error_of(const std::string& text) {
  try {
    parse_json_text(text, "doc.json");
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(Range, RuleTextAndBoundaries) {
  EXPECT_EQ(Range::greater_than(0).rule(), "must be > 0");
  EXPECT_EQ(Range::at_least(0).rule(), "must be >= 0");
  EXPECT_EQ(Range::at_most(2.5).rule(), "must be <= 2.5");
  EXPECT_EQ(Range::closed(0, 1).rule(), "must be in [0, 1]");
  EXPECT_EQ(Range::left_open(0, 0.1).rule(), "must be in (0, 0.1]");
  EXPECT_EQ(Range::open(-1, 1).labelled("-one", "one").rule(), "must be in (-one, one)");

  EXPECT_FALSE(Range::greater_than(0).contains(0.0));
  EXPECT_TRUE(Range::greater_than(0).contains(std::numeric_limits<double>::denorm_min()));
  EXPECT_TRUE(Range::closed(0, 1).contains(0.0));
  EXPECT_TRUE(Range::closed(0, 1).contains(1.0));
  EXPECT_FALSE(Range::closed(0, 1).contains(std::nextafter(1.0, 2.0)));
  EXPECT_FALSE(Range::left_open(0, 0.1).contains(0.0));
  EXPECT_TRUE(Range::left_open(0, 0.1).contains(0.1));
  EXPECT_FALSE(Range::open(-1, 1).contains(1.0));
  EXPECT_FALSE(Range::closed(0, 1).contains(std::nan("")));
}

TEST(ReadNumber, RangeErrorNamesPathRuleAndValueAsWritten) {
  const auto messages =
      messages_of(json::parse(R"({"contact": {"friction": -0.3}})"), [](ObjectReader& root) {
        auto contact = root.object("contact");
        EXPECT_FALSE(contact.number("friction", Range::at_least(0)).has_value());
        contact.finish();
      });
  EXPECT_THAT(messages, ElementsAre("test.json: /contact/friction: must be >= 0 (got -0.3)"));
}

TEST(ReadNumber, RefusesNonNumbersWithTheirKind) {
  const json document = json::parse(
      R"({"nan": "NaN", "inf": "-Infinity", "text": "0.6", "flag": true, "nothing": null, "list": [1], "map": {}})");
  const auto messages = messages_of(document, [](ObjectReader& root) {
    for (const char* key : {"nan", "inf", "text", "flag", "nothing", "list", "map"}) {
      EXPECT_FALSE(root.number(key).has_value()) << key;
    }
  });
  EXPECT_THAT(
      messages,
      ElementsAre(
          "test.json: /nan: must be a finite number (got \"NaN\"; JSON has no NaN or Infinity)",
          "test.json: /inf: must be a finite number (got \"-Infinity\"; JSON has no NaN or "
          "Infinity)",
          "test.json: /text: must be a number, not a string (got \"0.6\")",
          "test.json: /flag: must be a number (got true)",
          "test.json: /nothing: must be a number (got null)",
          "test.json: /list: must be a number (got an array)",
          "test.json: /map: must be a number (got an object)"));
}

TEST(ReadNumber, RefusesNonFiniteValuesBuiltInCode) {
  json document;
  document["a"] = std::nan("");
  document["b"] = -std::numeric_limits<double>::infinity();
  const auto messages = messages_of(document, [](ObjectReader& root) {
    root.number("a");
    root.number("b");
  });
  EXPECT_THAT(messages, ElementsAre("test.json: /a: must be a finite number (got nan)",
                                    "test.json: /b: must be a finite number (got -inf)"));
}

TEST(ReadInteger, AcceptsWholeNumbersOnly) {
  const json document = json::parse(
      R"({"plain": 3, "exponent": 1e6, "half": 2.5, "negative": -4, "huge": 18446744073709551615, "text": "7"})");
  const auto messages = messages_of(document, [](ObjectReader& root) {
    EXPECT_EQ(root.integer("plain"), 3);
    EXPECT_EQ(root.integer("exponent"), 1000000);  // written as a float, but an integer
    EXPECT_FALSE(root.integer("half").has_value());
    EXPECT_FALSE(root.integer("negative", Range::greater_than(0)).has_value());
    EXPECT_FALSE(root.integer("huge").has_value());
    EXPECT_FALSE(root.integer("text").has_value());
  });
  EXPECT_THAT(
      messages,
      ElementsAre(
          "test.json: /half: must be an integer (got 2.5)",
          "test.json: /negative: must be > 0 (got -4)",
          "test.json: /huge: must be an integer that fits in 64 bits (got 18446744073709551615)",
          "test.json: /text: must be a number, not a string (got \"7\")"));
}

TEST(ObjectReader, DefaultsRequiredAndChoices) {
  const json document = json::parse(R"({"kind": "sine", "flag": false, "name": "x", "count": 2})");
  const auto messages = messages_of(document, [](ObjectReader& root) {
    EXPECT_EQ(root.number_or("absent", 9.81), 9.81);
    EXPECT_EQ(root.integer_or("count", 7), 2);
    EXPECT_EQ(root.boolean_or("flag", true), false);
    EXPECT_EQ(root.string_or("name", "y"), "x");
    EXPECT_FALSE(root.required_number("needed").has_value());
    EXPECT_FALSE(root.required_choice("kind", {"cosine", "sines"}).has_value());
    EXPECT_FALSE(root.choice("absent_choice", {"a"}).has_value());
  });
  EXPECT_THAT(
      messages,
      ElementsAre("test.json: /needed: is required",
                  "test.json: /kind: must be one of \"cosine\", \"sines\" (got \"sine\"; did you "
                  "mean \"sines\"?)"));
}

TEST(ObjectReader, UnknownKeysGetTheNearestKnownKeyOrTheList) {
  const json document = json::parse(R"({"frction": 0.6, "restitution": 0.5, "zzz": 1})");
  const auto messages = messages_of(document, [](ObjectReader& root) {
    root.number("friction");
    root.number("restitution");
  });
  EXPECT_THAT(messages,
              ElementsAre("test.json: /frction: unknown key; did you mean \"friction\"?",
                          "test.json: /zzz: unknown key (known keys: friction restitution)"));
}

// A file's keys and strings are its content: a message quotes a short printable excerpt of them,
// however long or binary they are.
TEST(ObjectReader, MessagesQuoteAtMostAnExcerptOfTheFilesKeysAndStrings) {
  json document;
  document[std::string(300, 'k') + "\x01"] = 1;
  document["friction"] = "secret-" + std::string(300, 's');
  const auto messages = messages_of(document, [](ObjectReader& root) { root.number("friction"); });
  ASSERT_EQ(messages.size(), 2u);
  for (const auto& message : messages) {
    EXPECT_LT(message.size(), 200u) << message;
    EXPECT_EQ(message.find('\x01'), std::string::npos);
  }
  EXPECT_THAT(messages[0],
              ::testing::StartsWith(
                  "test.json: /friction: must be a number, not a string (got \"secret-sss"));
  EXPECT_THAT(messages[1], ::testing::StartsWith("test.json: /kkkkkkkk"));
  EXPECT_THAT(messages[1], ::testing::HasSubstr("...: unknown key"));
}

TEST(ObjectReader, FinishNamesTheContext) {
  ConfigErrors errors("s.json");
  const json object = json::parse(R"({"type": "cosine_pulse", "duration": 1})");
  ObjectReader reader(object, JsonPointer("/ground_motion"), errors);
  reader.string("type");
  reader.number("period");
  reader.finish("for type \"cosine_pulse\"");
  ASSERT_EQ(errors.size(), 1u);
  try {
    errors.throw_if_any();
    FAIL() << "accepted";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "s.json: /ground_motion/duration: unknown key for type \"cosine_pulse\" (known keys: "
              "period type)");
  }
}

TEST(ObjectReader, MissingOrWrongObjectsDoNotCascade) {
  const json document = json::parse(R"({"block": 3})");
  const auto messages = messages_of(document, [](ObjectReader& root) {
    auto block = root.required_object("block");
    EXPECT_FALSE(block.valid());
    block.required_number("half_width");
    block.finish();
    auto contact = root.required_object("contact");
    contact.required_number("friction");
    contact.finish();
  });
  EXPECT_THAT(messages, ElementsAre("test.json: /block: must be an object (got 3)",
                                    "test.json: /contact: is required"));
}

TEST(ObjectReader, RootThatIsNotAnObject) {
  const auto messages =
      messages_of(json::parse("[1, 2]"), [](ObjectReader& root) { root.number("a"); });
  EXPECT_THAT(messages, ElementsAre("test.json: must be an object (got an array)"));
}

TEST(ObjectReader, PointersEscapeSlashAndTilde) {
  const auto messages = messages_of(json::parse(R"({"a/b": {"c~d": -1}})"), [](ObjectReader& root) {
    auto inner = root.object("a/b");
    inner.number("c~d", Range::at_least(0));
    inner.finish();
  });
  EXPECT_THAT(messages, ElementsAre("test.json: /a~1b/c~0d: must be >= 0 (got -1)"));
}

TEST(ObjectReader, CrossFieldErrorsAndEveryErrorTogether) {
  const json document = json::parse(R"({"low": 5, "high": 2, "rate": -1, "extra": 0})");
  ConfigErrors errors("study.json");
  ObjectReader root(document, JsonPointer{}, errors);
  const auto low = root.number("low");
  const auto high = root.number("high");
  root.number("rate", Range::greater_than(0));
  if (low && high && *low > *high) root.add_error("high", "must be >= low (5) (got 2)");
  root.finish();
  try {
    errors.throw_if_any();
    FAIL() << "accepted";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "study.json: /rate: must be > 0 (got -1)\n"
              "study.json: /high: must be >= low (5) (got 2)\n"
              "study.json: /extra: unknown key (known keys: high low rate)");
    EXPECT_EQ(error.messages().size(), 3u);
  }
}

TEST(ArrayReader, ElementsHaveIndexedPaths) {
  const json document = json::parse(R"({"levels": [0.1, -2, "x", {"name": 1}], "scalar": 1})");
  const auto messages = messages_of(document, [](ObjectReader& root) {
    auto levels = root.required_array("levels");
    ASSERT_EQ(levels.size(), 4u);
    EXPECT_EQ(levels.number(0, Range::greater_than(0)), 0.1);
    EXPECT_FALSE(levels.number(1, Range::greater_than(0)).has_value());
    EXPECT_FALSE(levels.string(3).has_value());
    auto object = levels.object(3);
    object.string("name");
    object.finish();
    auto not_array = root.array("scalar");
    EXPECT_EQ(not_array.size(), 0u);
  });
  EXPECT_THAT(messages, ElementsAre("test.json: /levels/1: must be > 0 (got -2)",
                                    "test.json: /levels/3: must be a string (got an object)",
                                    "test.json: /levels/3/name: must be a string (got 1)",
                                    "test.json: /scalar: must be an array (got 1)"));
}

TEST(EditDistance, KnownValues) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("abc", "abc"), 0u);
  EXPECT_EQ(edit_distance("frction", "friction"), 1u);
  EXPECT_EQ(edit_distance("firction", "friction"), 1u);  // one transposition
  EXPECT_EQ(edit_distance("ca", "abc"), 3u);             // OSA, not full Damerau (which gives 2)
}

TEST(ClosestMatch, SuggestsOnlyPlausibleTypos) {
  const std::vector<std::string> keys = {"friction", "restitution", "g", "amplitude_g", "type"};
  EXPECT_EQ(closest_match("frction", keys), "friction");
  EXPECT_EQ(closest_match("Friction", keys), "friction");
  EXPECT_EQ(closest_match("amplitude", keys), "amplitude_g");
  EXPECT_EQ(closest_match("typ", keys), "type");
  EXPECT_FALSE(closest_match("e", keys).has_value());  // one letter from "g", but not a typo of it
  EXPECT_FALSE(closest_match("mu", keys).has_value());
}

TEST(ParseJsonText, MalformedTextGivesLineAndColumn) {
  // '@' is on line 3, after two spaces and `"b": ` : column 8.
  EXPECT_THAT(parse_error_of("{\n  \"a\": 1,\n  \"b\": @\n}"),
              HasSubstr("doc.json:3:8: malformed JSON: syntax error while parsing value"));
  // A missing comma: the parser stops at the second key's opening quote, line 2 column 2.
  EXPECT_THAT(parse_error_of("{\"a\": 1\n \"b\": 2}"),
              HasSubstr("doc.json:2:2: malformed JSON: syntax error"));
  EXPECT_THAT(parse_error_of(""), HasSubstr("doc.json:1:1: malformed JSON: syntax error"));
  // Unterminated object: the end of input is at line 2, column 1.
  EXPECT_THAT(parse_error_of("{\"a\": 1,\n"), HasSubstr("doc.json:2:1: malformed JSON"));
  // Columns count characters: the two-byte u-umlaut is one column.
  EXPECT_THAT(parse_error_of("{\"\xc3\xbc\": @}"), HasSubstr("doc.json:1:7: malformed JSON"));
  EXPECT_THAT(parse_error_of("{\"a\": NaN}"), HasSubstr("doc.json:1:7: malformed JSON"));
  EXPECT_THAT(parse_error_of("{\"a\": 1e999}"),
              HasSubstr("malformed JSON: number overflow parsing '1e999'"));
}

TEST(ParseJsonText, QuotesAtMostAnExcerptOfTheTokenThatBrokeTheParse) {
  // An unterminated string of 1 MB: the lexer's token is all of it.
  const std::string unterminated = parse_error_of("{\"a\": \"" + std::string(1'000'000, 'x'));
  EXPECT_THAT(unterminated, HasSubstr("malformed JSON: syntax error"));
  EXPECT_THAT(unterminated, HasSubstr("last read: '\"" + std::string(59, 'x') + "...'"));
  EXPECT_LT(unterminated.size(), 300u);
  // A string broken by a newline: the token is the line up to it, the rest of the line unquoted.
  const std::string broken =
      parse_error_of("{\"a\": \"" + std::string(100, 'y') + "\nSECRET-REST\"}");
  EXPECT_THAT(broken, HasSubstr("last read: '\"" + std::string(59, 'y') + "...'"));
  EXPECT_THAT(broken, Not(HasSubstr("yyyyy<U+000A>")));
  EXPECT_THAT(broken, Not(HasSubstr("SECRET")));
  // A number too large for a double, written with 100,000 digits.
  const std::string overflow = parse_error_of("{\"a\": 1" + std::string(100'000, '0') + "}");
  EXPECT_THAT(overflow, HasSubstr("number overflow parsing '1" + std::string(59, '0') + "...'"));
  EXPECT_LT(overflow.size(), 300u);
  // A short token is quoted whole.
  EXPECT_THAT(parse_error_of("{\"a\": \"ab\ncd\"}"), HasSubstr("last read: '\"ab<U+000A>'"));
}

TEST(ParseJsonText, DuplicateKeysAreErrorsWithTheirPaths) {
  try {
    parse_json_text(R"({"a": {"b": 1, "b": 2}, "list": [{"x": 1}, {"x": 1, "x": 2}], "c": 3})",
                    "doc.json");
    FAIL() << "accepted";
  } catch (const ConfigError& error) {
    EXPECT_THAT(error.messages(),
                ElementsAre("doc.json: /a/b: duplicate key", "doc.json: /list/1/x: duplicate key"));
  }
}

TEST(ParseJsonText, BuildsTheSameDocumentAsNlohmann) {
  const std::string text =
      R"({"a": [1, -2, 3.5, 1e-300, 18446744073709551615, true, false, null, "s\u00fc"],
    "b": {"c": {"d": []}, "e": {}}, "f": [[1, [2]], {"g": [{"h": 0.1}]}], "": -0.0})";
  const json ours = parse_json_text(text, "doc.json");
  EXPECT_EQ(ours, json::parse(text));
  EXPECT_EQ(ours.dump(), json::parse(text).dump());
  EXPECT_EQ(parse_json_text("42", "doc.json"), json(42));
}

TEST(ReadJsonFile, MissingFileIsASystemError) {
  EXPECT_THROW(read_json_file("/nonexistent/scene.json"), InputFileError);
}

TEST(ReadJsonFile, NamesTheFileAsGiven) {
  try {
    read_json_file(std::string(BLOCKFRAG_SOURCE_DIR) +
                   "/tests/data/bad_scenes/malformed_missing_comma.json");
    FAIL() << "accepted";
  } catch (const ConfigError& error) {
    EXPECT_THAT(
        error.what(),
        HasSubstr("tests/data/bad_scenes/malformed_missing_comma.json:4:3: malformed JSON"));
  }
}

}  // namespace
}  // namespace blockfrag
