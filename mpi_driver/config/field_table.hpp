// One table per config struct: each entry is a JSON key, the member it fills, the member's domain
// (engine/scene/parameter_domains.hpp) and whether the key is required. read_fields reads the
// keys, write_fields writes them into the canonical form (the config hash) and describe_fields
// lists them for the docs' key tables (tests/unit/driver/config_key_tables_test.cpp compares
// docs/scenes.md, studies.md and spectra.md with them), so a key added to a table is read, hashed
// and documented at once.
// What a table cannot say (a key that selects other keys, a rule across keys) stays with the
// struct's reader, which calls read_fields for the rest.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/number_text.hpp"
#include "engine/scene/parameter_domains.hpp"
#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

enum class Presence { required, optional };

enum class Written {
  always,
  // Only a value other than the struct's default: a key added after configs without it were
  // hashed, so that those keep their hash.
  unless_default,
};

// An enum member, read and written by the names of its EnumNames
// (mpi_driver/config/enum_names.hpp).
template <class Struct>
struct ChoiceMember {
  std::span<const std::string_view> names;
  std::string_view (*get)(const Struct&);
  void (*set)(Struct&, std::string_view);
};

namespace field_detail {
template <class MemberPointer>
struct MemberOf;
template <class Struct, class Value>
struct MemberOf<Value Struct::*> {
  using type = Struct;
};
template <class... Visitors>
struct Overloaded : Visitors... {
  using Visitors::operator()...;
};
template <class... Visitors>
Overloaded(Visitors...) -> Overloaded<Visitors...>;
}  // namespace field_detail

template <auto member, const auto& enum_names>
constexpr auto choice_member() {
  using Struct = typename field_detail::MemberOf<decltype(member)>::type;
  return ChoiceMember<Struct>{
      enum_names.names, [](const Struct& s) { return enum_names.name(s.*member); },
      [](Struct& s, std::string_view name) { s.*member = *enum_names.value(name); }};
}

// A member that must be 1 or -1 (a fixed direction of the ground motion).
template <class Struct>
struct SignMember {
  double Struct::*member;
};

// An array of increasing numbers (a study's levels, a spectrum axis's values), each in the field's
// domain, as many as `count` allows; `noun` names one in messages ("level").
struct IncreasingNumbers {
  const Domain* count;
  std::string_view noun;
};
template <class Struct>
struct IncreasingMember {
  std::vector<double> Struct::*member;
  IncreasingNumbers rule;
};

// Reads the array `key` into `out`; whether it was given and valid. Its numbers that are valid
// are kept either way, so that the rules after it can still be checked.
bool read_increasing_numbers(ObjectReader& reader, std::string_view key, const Range& range,
                             const IncreasingNumbers& rule, bool required,
                             std::vector<double>& out);

template <class Struct>
struct Field {
  using Member =
      std::variant<double Struct::*, std::optional<double> Struct::*, long Struct::*, int Struct::*,
                   std::uint32_t Struct::*, std::uint64_t Struct::*, bool Struct::*,
                   std::string Struct::*, std::filesystem::path Struct::*, SignMember<Struct>,
                   IncreasingMember<Struct>, ChoiceMember<Struct>>;
  std::string_view key;
  Member member;
  // nullptr for a choice, a boolean, a string or a sign; each number's for an array.
  const Domain* domain;
  Presence presence = Presence::optional;
  Written written = Written::always;
  // What the canonical form writes for an optional member, where its absence resolves to a value
  // (a Ricker wavelet's centre): the form then names the same motion after any default changes.
  // Without it an absent optional member is not written.
  double (*resolved)(const Struct&) = nullptr;
};

// The keys that were given with a valid value.
class FieldsRead {
 public:
  void add(std::string_view key) { valid_.push_back(key); }
  bool valid(std::string_view key) const {
    for (const std::string_view given : valid_) {
      if (given == key) return true;
    }
    return false;
  }

 private:
  std::vector<std::string_view> valid_;
};

namespace field_detail {

template <class Value>
constexpr bool is_integer_v =
    std::is_same_v<Value, long> || std::is_same_v<Value, int> ||
    std::is_same_v<Value, std::uint32_t> || std::is_same_v<Value, std::uint64_t>;

// Reads one field's key into `out`; whether it was given with a valid value.
template <class Struct>
bool read_field(ObjectReader& reader, const Field<Struct>& field, Struct& out) {
  const bool required = field.presence == Presence::required;
  const Range range = field.domain ? Range::of(*field.domain) : Range::any();
  const auto number = [&] {
    return required ? reader.required_number(field.key, range) : reader.number(field.key, range);
  };
  const auto store = [&](auto& member, const auto& value) {
    if (value) member = static_cast<std::remove_reference_t<decltype(member)>>(*value);
    return value.has_value();
  };
  const auto text = [&] {
    return required ? reader.required_string(field.key) : reader.string(field.key);
  };
  return std::visit(
      Overloaded{[&](std::optional<double> Struct::*member) {
                   out.*member = number();
                   return (out.*member).has_value();
                 },
                 [&](bool Struct::*member) {
                   return store(out.*member, required ? reader.required_boolean(field.key)
                                                      : reader.boolean(field.key));
                 },
                 [&](std::string Struct::*member) { return store(out.*member, text()); },
                 [&](std::filesystem::path Struct::*member) { return store(out.*member, text()); },
                 [&](const SignMember<Struct>& sign) {
                   const auto value = number();
                   if (value && *value != 1.0 && *value != -1.0) {
                     reader.add_error(field.key,
                                      "must be 1 or -1 (got " + format_number(*value) + ")");
                     return false;
                   }
                   return store(out.*(sign.member), value);
                 },
                 [&](const IncreasingMember<Struct>& numbers) {
                   return read_increasing_numbers(reader, field.key, range, numbers.rule, required,
                                                  out.*(numbers.member));
                 },
                 [&](const ChoiceMember<Struct>& choice) {
                   const auto name = required ? reader.required_choice(field.key, choice.names)
                                              : reader.choice(field.key, choice.names);
                   if (name) choice.set(out, *name);
                   return name.has_value();
                 },
                 [&]<class Value>(Value Struct::*member) {
                   if constexpr (is_integer_v<Value>) {
                     return store(out.*member, required ? reader.required_integer(field.key, range)
                                                        : reader.integer(field.key, range));
                   } else {
                     return store(out.*member, number());
                   }
                 }},
      field.member);
}

}  // namespace field_detail

// Reads every field's key into `out`, in the table's order; an absent optional key or an invalid
// value leaves the member as it was (an optional<double> member is reset), the errors recorded at
// the key's path. The reader's finish() stays with the caller.
template <class Struct>
FieldsRead read_fields(ObjectReader& reader,
                       std::type_identity_t<std::span<const Field<Struct>>> fields, Struct& out) {
  FieldsRead read;
  for (const Field<Struct>& field : fields) {
    if (field_detail::read_field(reader, field, out)) read.add(field.key);
  }
  return read;
}

// Writes every field of `in` into the object `out` (a member equal to its default too, unless the
// field says Written::unless_default; an array always).
template <class Struct>
void write_fields(const Struct& in, std::type_identity_t<std::span<const Field<Struct>>> fields,
                  nlohmann::json& out) {
  // gcc's -Warray-bounds sees every alternative's member read from this object: a struct smaller
  // than a double (a lone bool) draws a false warning.
  static const Struct defaults{};
  for (const Field<Struct>& field : fields) {
    const std::string key(field.key);
    const auto write = [&](const auto& value, const auto& fallback) {
      if (field.written == Written::unless_default && value == fallback) return;
      out[key] = value;
    };
    std::visit(
        field_detail::Overloaded{
            [&](std::optional<double> Struct::*member) {
              if (field.resolved) {
                out[key] = field.resolved(in);
              } else if (in.*member) {
                out[key] = *(in.*member);
              }
            },
            [&](const SignMember<Struct>& sign) {
              write(in.*(sign.member), defaults.*(sign.member));
            },
            [&](const IncreasingMember<Struct>& numbers) { out[key] = in.*(numbers.member); },
            [&](std::filesystem::path Struct::*member) { out[key] = (in.*member).string(); },
            [&](const ChoiceMember<Struct>& choice) { out[key] = std::string(choice.get(in)); },
            [&]<class Value>(Value Struct::*member) { write(in.*member, defaults.*member); }},
        field.member);
  }
}

// What kind of value a key takes, as the docs' key tables say it.
enum class FieldKind { number, integer, numbers, choice, boolean, text, sign };

// What the docs' key tables say of a key.
struct FieldDescription {
  std::string key;
  FieldKind kind = FieldKind::number;
  std::optional<Domain> domain;  // a number's or an integer's, each of an array's numbers
  bool required = false;
  std::vector<std::string> choices;
};

// A table's descriptions under the prefix a docs' key table names its keys with ("block.").
struct KeyTable {
  std::string prefix;
  std::vector<FieldDescription> fields;
};

template <class Struct>
std::vector<FieldDescription> describe_fields(
    std::type_identity_t<std::span<const Field<Struct>>> fields) {
  std::vector<FieldDescription> described;
  for (const Field<Struct>& field : fields) {
    FieldDescription description;
    description.key = field.key;
    if (field.domain) description.domain = *field.domain;
    description.required = field.presence == Presence::required;
    description.kind = std::visit(
        field_detail::Overloaded{
            [](bool Struct::*) { return FieldKind::boolean; },
            [](std::string Struct::*) { return FieldKind::text; },
            [](std::filesystem::path Struct::*) { return FieldKind::text; },
            [](const SignMember<Struct>&) { return FieldKind::sign; },
            [](const IncreasingMember<Struct>&) { return FieldKind::numbers; },
            [&](const ChoiceMember<Struct>& choice) {
              description.choices.assign(choice.names.begin(), choice.names.end());
              return FieldKind::choice;
            },
            []<class Value>(Value Struct::*) {
              return field_detail::is_integer_v<Value> ? FieldKind::integer : FieldKind::number;
            }},
        field.member);
    described.push_back(std::move(description));
  }
  return described;
}

// The descriptions of every alternative of a variant whose keys a trait holds,
// Keys<Alternative>::fields (a ground motion's type, a distribution's law), in the variant's order.
template <class Variant, template <class> class Keys>
std::vector<FieldDescription> describe_alternatives() {
  std::vector<FieldDescription> described;
  [&]<std::size_t... index>(std::index_sequence<index...>) {
    const auto add = [&](std::vector<FieldDescription> fields) {
      for (FieldDescription& field : fields) described.push_back(std::move(field));
    };
    (add(describe_fields<std::variant_alternative_t<index, Variant>>(
         Keys<std::variant_alternative_t<index, Variant>>::fields)),
     ...);
  }
  (std::make_index_sequence<std::variant_size_v<Variant>>{});
  return described;
}

}  // namespace blockfrag
