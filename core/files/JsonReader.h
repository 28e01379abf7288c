#pragma once
// Reads fields of a JSON object with the path of each field kept, so every error names where
// it happened ("ga.population: must be an integer in [2, 100000], got 0"). Fields that are
// present but never read are reported as warnings. Errors throw JsonFieldError; the public
// loaders turn it into a Result.
#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/Result.h"
#include "common/ShortText.h"

namespace matevo {

// The message is kept visible (common/ShortText.h): what() is a C string, which a NUL in a quoted
// value would cut.
struct JsonFieldError : std::runtime_error {
    explicit JsonFieldError(const std::string& message)
        : std::runtime_error(visibleText(message)) {}
};

class JsonReader {
public:
    // `path` is the dotted location of `object` ("" for the root).
    JsonReader(const nlohmann::json& object, std::string path, std::vector<std::string>& warnings);

    bool has(const std::string& key) const;
    double number(const std::string& key, double min, double max);
    long long integer(const std::string& key, long long min, long long max);
    std::uint64_t unsignedInteger(const std::string& key);  // the full 64-bit range
    bool boolean(const std::string& key);
    std::string string(const std::string& key);
    template <std::size_t N>
    std::array<double, N> numbers(const std::string& key, double min, double max);
    JsonReader object(const std::string& key);
    // A string naming one value of an enumeration; `expected` lists them for the error.
    template <typename Enum>
    Enum enumeration(const std::string& key, std::optional<Enum> (*parse)(std::string_view),
                     const std::string& expected);
    // An array of objects, one reader each; their errors name "key[i].field".
    std::vector<JsonReader> objects(const std::string& key);

    // Call once every known field was read: warns about the others.
    void warnAboutUnknownFields();

    void warn(const std::string& key, const std::string& problem);
    [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

private:
    const nlohmann::json& field(const std::string& key);
    std::string fieldPath(const std::string& key) const;
    static double checkedNumber(const nlohmann::json& value, const std::string& where, double min,
                                double max);

    const nlohmann::json& object_;
    std::string path_;
    std::vector<std::string>& warnings_;
    std::set<std::string> read_;
};

// An integer read back from a JSON file matevo wrote (reports, shares, checkpoints), which a
// user may have edited: nlohmann's get<int>() converts a float or an out-of-range number with a
// plain cast (1e62 to int is undefined behaviour). Throws the library's type_error, as get<int>()
// does for a string, so a reader's catch of nlohmann's exceptions names the field.
template <typename Integer, typename Json>
Integer jsonInteger(const Json& value) {
    if (value.is_number_unsigned()) {
        if (const auto number = value.template get<std::uint64_t>(); std::in_range<Integer>(number))
            return Integer(number);
    } else if (value.is_number_integer()) {
        if (const auto number = value.template get<std::int64_t>(); std::in_range<Integer>(number))
            return Integer(number);
    }
    throw Json::type_error::create(
        302, "must be an integer that fits the field, got " + value.dump(), &value);
}

// Every JSON text matevo reads is nested at most this deep. Parsers recurse once per level
// (tinygltf turns each level into a nested Value), so a document 20,000 levels deep overflows the
// stack; no file matevo reads or writes comes near this.
constexpr std::size_t kMaxJsonNesting = 256;

// Checks the nesting of arrays and objects in `text` without parsing it, for every JSON reader to
// call before a parser sees the text. The error names `sourceName` and the byte where the limit
// was passed.
Status checkJsonNesting(std::string_view text, const std::string& sourceName);

// Parses a JSON document after checkJsonNesting; errors name `sourceName`.
template <typename Json>
Result<Json> parseJsonDocument(const std::string& jsonText, const std::string& sourceName) {
    if (auto nesting = checkJsonNesting(jsonText, sourceName); !nesting) return nesting.error();
    try {
        return Json::parse(jsonText);
    } catch (const typename Json::exception& error) {
        return badInput(sourceName + ": not valid JSON (" + error.what() + ")");
    }
}

// Parses a JSON document and reads it with `read(const nlohmann::json&)`, which may throw
// JsonFieldError: a syntax error or a field error becomes an Error naming `sourceName`, and the
// warnings gathered while reading are prefixed with it.
template <typename T, typename Read>
Result<T> readJsonDocument(const std::string& jsonText, const std::string& sourceName,
                           std::vector<std::string>& warnings, Read&& read) {
    auto json = parseJsonDocument<nlohmann::json>(jsonText, sourceName);
    if (!json) return json.error();
    try {
        T value = read(*json);
        for (auto& warning : warnings) warning = sourceName + ": " + warning;
        return value;
    } catch (const nlohmann::json::exception& error) {  // a reader's get<T>() on a wrong type
        return badInput(sourceName + ": not valid JSON (" + error.what() + ")");
    } catch (const JsonFieldError& error) {
        return badInput(sourceName + ": " + error.what());
    }
}

template <std::size_t N>
std::array<double, N> JsonReader::numbers(const std::string& key, double min, double max) {
    const auto& value = field(key);
    if (!value.is_array() || value.size() != N)
        fail(key, "must be an array of " + std::to_string(N) + " numbers");
    std::array<double, N> result{};
    for (std::size_t i = 0; i < N; ++i)
        result[i] =
            checkedNumber(value[i], fieldPath(key) + "[" + std::to_string(i) + "]", min, max);
    return result;
}

template <typename Enum>
Enum JsonReader::enumeration(const std::string& key, std::optional<Enum> (*parse)(std::string_view),
                             const std::string& expected) {
    auto text = string(key);
    auto value = parse(text);
    if (!value) fail(key, "unknown value '" + text + "' (expected " + expected + ")");
    return *value;
}

}  // namespace matevo
