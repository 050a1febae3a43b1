// Checks of the JSON writers of Options and Report structs: field_count, the number of members of
// an aggregate (a base class counts as one), found by brace-initialising it from ever more
// "convert to anything" values, and expect_fields, which compares a writer's JSON with a hand
// list of (key, value). A test compares the list's length with field_count, so that a field added
// to a struct without a writer line fails.
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace tapeline::test {

namespace detail {
struct AnyField {
    // A reference conversion: copy-initialising std::string from a by-value conversion would be
    // ambiguous (string and string_view constructors).
    template <class T>
    operator T&() const;
    template <class T>
    operator T&&() const;
};

template <class T, class Seq, class = void>
struct brace_constructible : std::false_type {};
template <class T, std::size_t... I>
struct brace_constructible<T, std::index_sequence<I...>,
                           std::void_t<decltype(T{(void(I), AnyField{})...})>> : std::true_type {};

template <class T, std::size_t N>
constexpr std::size_t count_fields() {
    if constexpr (N > 80) {
        return N;
    } else if constexpr (brace_constructible<T, std::make_index_sequence<N + 1>>::value) {
        return count_fields<T, N + 1>();
    } else {
        return N;
    }
}
}  // namespace detail

template <class T>
constexpr std::size_t field_count() {
    static_assert(std::is_aggregate_v<T>, "field_count needs an aggregate");
    return detail::count_fields<T, 0>();
}

using JsonFields = std::vector<std::pair<std::string, nlohmann::json>>;

/// `j` is an object holding exactly `fields`, each with the given value.
inline void expect_fields(const nlohmann::json& j, const JsonFields& fields,
                          const std::string& what) {
    ASSERT_TRUE(j.is_object()) << what;
    for (const auto& [name, value] : fields) {
        ASSERT_TRUE(j.contains(name)) << what << ": no '" << name << "'";
        EXPECT_EQ(j[name], value) << what << "." << name;
    }
    EXPECT_EQ(j.size(), fields.size()) << what << ": " << j.dump();
}

}  // namespace tapeline::test

/// A (key, value) entry of a JsonFields list: the member's C++ name and its value as JSON.
#define TAPELINE_JSON_FIELD(object, name) \
    ::tapeline::test::JsonFields::value_type(#name, ::nlohmann::json((object).name))
