#include "mesh/ObjReader.h"

#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>
#include <string_view>
#include <tuple>
#include <vector>

namespace matevo {
namespace {

struct LineError {
    std::string message;
};

std::vector<std::string_view> splitWords(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t begin = 0;
    while (begin < line.size()) {
        while (begin < line.size() && (line[begin] == ' ' || line[begin] == '\t')) ++begin;
        std::size_t end = begin;
        while (end < line.size() && line[end] != ' ' && line[end] != '\t') ++end;
        if (end > begin) words.push_back(line.substr(begin, end - begin));
        begin = end;
    }
    return words;
}

float parseFloat(std::string_view word) {
    float value = 0.0f;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value))
        throw LineError{"'" + std::string(word) + "' is not a finite number"};
    return value;
}

// Reads `count` numbers after the keyword (extra ones, such as a w or a vertex colour, are
// allowed and ignored).
template <int count>
std::array<float, count> parseNumbers(const std::vector<std::string_view>& words) {
    if (int(words.size()) < count + 1)
        throw LineError{"'" + std::string(words[0]) + "' needs " + std::to_string(count) +
                        " numbers"};
    std::array<float, count> values{};
    for (int i = 0; i < count; ++i) values[std::size_t(i)] = parseFloat(words[std::size_t(i) + 1]);
    return values;
}

// A 1-based or negative (relative) OBJ index into a list of `size` items, as a 0-based index;
// -1 for an empty field.
long resolveIndex(std::string_view field, std::size_t size, const char* what) {
    if (field.empty()) return -1;
    long value = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error != std::errc() || end != field.data() + field.size() || value == 0)
        throw LineError{"'" + std::string(field) + "' is not a valid " + what + " index"};
    const long resolved = value > 0 ? value - 1 : long(size) + value;
    if (resolved < 0 || resolved >= long(size))
        throw LineError{std::string(what) + " index " + std::string(field) + " out of range (" +
                        std::to_string(size) + " " + what + "s)"};
    return resolved;
}

struct ObjData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec3> normals;
    // Each distinct (position, uv, normal) triple becomes one mesh vertex.
    std::map<std::tuple<long, long, long>, std::uint32_t> vertexOf;
    bool missingNormals = false;
    Mesh mesh;

    std::uint32_t faceVertex(std::string_view corner) {
        std::array<std::string_view, 3> fields;
        std::size_t field = 0, begin = 0;
        for (std::size_t i = 0; i <= corner.size(); ++i) {
            if (i == corner.size() || corner[i] == '/') {
                if (field == 3) throw LineError{"'" + std::string(corner) + "' has too many '/'"};
                fields[field++] = corner.substr(begin, i - begin);
                begin = i + 1;
            }
        }
        const long position = resolveIndex(fields[0], positions.size(), "position");
        if (position < 0) throw LineError{"a face corner has no position index"};
        const long uv = resolveIndex(fields[1], uvs.size(), "texture coordinate");
        const long normal = resolveIndex(fields[2], normals.size(), "normal");
        const auto key = std::make_tuple(position, uv, normal);
        if (auto found = vertexOf.find(key); found != vertexOf.end()) return found->second;
        MeshVertex vertex;
        vertex.position = positions[std::size_t(position)];
        if (uv >= 0) vertex.uv = uvs[std::size_t(uv)];
        if (normal >= 0) {
            vertex.normal = normals[std::size_t(normal)];
        } else {
            missingNormals = true;
        }
        const auto index = std::uint32_t(mesh.vertices.size());
        mesh.vertices.push_back(vertex);
        vertexOf.emplace(key, index);
        return index;
    }
};

void parseLine(ObjData& data, std::string_view line) {
    if (const auto comment = line.find('#'); comment != std::string_view::npos)
        line = line.substr(0, comment);
    const auto words = splitWords(line);
    if (words.empty()) return;
    const std::string_view keyword = words[0];
    if (keyword == "v") {
        const auto xyz = parseNumbers<3>(words);
        data.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if (keyword == "vt") {
        const auto uv = parseNumbers<2>(words);
        // OBJ's v runs bottom to top; our images run top to bottom.
        data.uvs.emplace_back(uv[0], 1.0f - uv[1]);
    } else if (keyword == "vn") {
        const auto xyz = parseNumbers<3>(words);
        data.normals.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if (keyword == "f") {
        if (words.size() < 4) throw LineError{"a face needs at least three corners"};
        std::vector<std::uint32_t> corners;
        for (std::size_t i = 1; i < words.size(); ++i) corners.push_back(data.faceVertex(words[i]));
        for (std::size_t i = 1; i + 1 < corners.size(); ++i)
            data.mesh.indices.insert(data.mesh.indices.end(),
                                     {corners[0], corners[i], corners[i + 1]});
    }
    // Anything else (o, g, s, usemtl, mtllib, l, p, ...) does not change the surface.
}

}  // namespace

Result<Mesh> parseObj(const std::string& text, const std::string& sourceName) {
    ObjData data;
    std::istringstream lines(text);
    std::string line;
    int lineNumber = 0;
    while (std::getline(lines, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        try {
            parseLine(data, line);
        } catch (const LineError& error) {
            return badInput(sourceName + ":" + std::to_string(lineNumber) + ": " + error.message);
        }
    }
    if (data.mesh.indices.empty()) return badInput(sourceName + ": no faces (f lines) to draw");
    if (data.missingNormals) computeVertexNormals(data.mesh);
    return std::move(data.mesh);
}

}  // namespace matevo
