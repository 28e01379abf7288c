#include "files/JsonReader.h"

#include <cmath>
#include <sstream>

namespace matevo {

namespace {

std::string formatNumber(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

}  // namespace

Status checkJsonNesting(std::string_view text, const std::string& sourceName) {
    std::size_t depth = 0;
    bool inString = false;
    for (std::size_t at = 0; at < text.size(); ++at) {
        const char c = text[at];
        if (inString) {
            if (c == '\\')
                ++at;  // the escaped character cannot end the string
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonNesting)
                return badInput(sourceName + ": JSON nested deeper than " +
                                std::to_string(kMaxJsonNesting) + " levels (at byte " +
                                std::to_string(at) + ")");
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return Ok{};
}

JsonReader::JsonReader(const nlohmann::json& object, std::string path,
                       std::vector<std::string>& warnings)
    : object_(object), path_(std::move(path)), warnings_(warnings) {
    if (!object_.is_object())
        throw JsonFieldError((path_.empty() ? std::string("document") : path_) +
                             ": must be a JSON object");
}

bool JsonReader::has(const std::string& key) const { return object_.contains(key); }

const nlohmann::json& JsonReader::field(const std::string& key) {
    auto it = object_.find(key);
    if (it == object_.end()) fail(key, "missing");
    read_.insert(key);
    return *it;
}

std::string JsonReader::fieldPath(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
}

void JsonReader::warn(const std::string& key, const std::string& problem) {
    warnings_.push_back(fieldPath(key) + ": " + problem);
}

void JsonReader::fail(const std::string& key, const std::string& problem) const {
    throw JsonFieldError(fieldPath(key) + ": " + problem);
}

double JsonReader::checkedNumber(const nlohmann::json& value, const std::string& where, double min,
                                 double max) {
    if (!value.is_number()) throw JsonFieldError(where + ": must be a number");
    double number = value.get<double>();
    if (!std::isfinite(number) || number < min || number > max)
        throw JsonFieldError(where + ": must be in [" + formatNumber(min) + ", " +
                             formatNumber(max) + "], got " + formatNumber(number));
    return number;
}

double JsonReader::number(const std::string& key, double min, double max) {
    return checkedNumber(field(key), fieldPath(key), min, max);
}

long long JsonReader::integer(const std::string& key, long long min, long long max) {
    const auto& value = field(key);
    if (!value.is_number_integer()) {
        if (value.is_number_float() && std::isfinite(value.get<double>()))
            fail(key, "must be an integer, got " + formatNumber(value.get<double>()));
        fail(key, "must be an integer");
    }
    // Unsigned values beyond the signed range are out of every range we accept.
    if (value.is_number_unsigned() &&
        value.get<unsigned long long>() > static_cast<unsigned long long>(max))
        fail(key, "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
                      value.dump());
    long long number = value.get<long long>();
    if (number < min || number > max)
        fail(key, "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
                      std::to_string(number));
    return number;
}

std::uint64_t JsonReader::unsignedInteger(const std::string& key) {
    const auto& value = field(key);
    if (!value.is_number_unsigned()) fail(key, "must be a non-negative integer");
    return value.get<std::uint64_t>();
}

bool JsonReader::boolean(const std::string& key) {
    const auto& value = field(key);
    if (!value.is_boolean()) fail(key, "must be true or false");
    return value.get<bool>();
}

std::string JsonReader::string(const std::string& key) {
    const auto& value = field(key);
    if (!value.is_string()) fail(key, "must be a string");
    return value.get<std::string>();
}

JsonReader JsonReader::object(const std::string& key) {
    const auto& value = field(key);
    if (!value.is_object()) fail(key, "must be a JSON object");
    return JsonReader(value, fieldPath(key), warnings_);
}

std::vector<JsonReader> JsonReader::objects(const std::string& key) {
    const auto& value = field(key);
    if (!value.is_array()) fail(key, "must be an array of JSON objects");
    std::vector<JsonReader> readers;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string where = key + "[" + std::to_string(i) + "]";
        if (!value[i].is_object()) fail(where, "must be a JSON object");
        readers.emplace_back(value[i], fieldPath(where), warnings_);
    }
    return readers;
}

void JsonReader::warnAboutUnknownFields() {
    for (const auto& [key, value] : object_.items())
        if (!read_.count(key)) warn(key, "unknown field, ignored");
}

}  // namespace matevo
