#include "mesh/GeneratedMeshes.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

namespace matevo {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Adds triangle (a, b, c), wound counter-clockwise seen from the side its normals face;
// skips triangles of zero area (at poles and creases).
void addTriangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const glm::vec3 pa = mesh.vertices[a].position;
    const glm::vec3 faceNormal =
        glm::cross(mesh.vertices[b].position - pa, mesh.vertices[c].position - pa);
    if (glm::length(faceNormal) < 1e-12f) return;
    const glm::vec3 vertexNormals =
        mesh.vertices[a].normal + mesh.vertices[b].normal + mesh.vertices[c].normal;
    if (glm::dot(faceNormal, vertexNormals) >= 0.0f) {
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
    } else {
        mesh.indices.insert(mesh.indices.end(), {a, c, b});
    }
}

// A grid of (rows + 1) x (columns + 1) vertices, already in mesh.vertices from `first` on, row by
// row, joined into quads of two triangles each.
void addGridTriangles(Mesh& mesh, std::uint32_t first, int rows, int columns) {
    const auto at = [&](int row, int column) {
        return first + std::uint32_t(row * (columns + 1) + column);
    };
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            addTriangle(mesh, at(row, column), at(row + 1, column), at(row + 1, column + 1));
            addTriangle(mesh, at(row, column), at(row + 1, column + 1), at(row, column + 1));
        }
    }
}

// One point of a surface of revolution's profile: radius from the y axis, height, and the
// outward normal in the (radius, height) plane. A crease repeats a point with another normal.
struct ProfilePoint {
    float radius;
    float height;
    glm::vec2 normal;
};

// Revolves the profile (top to bottom) around +y; u follows the sphere's mapping (u = 0.5
// faces +z), v the profile's arc length.
Mesh makeLathe(const std::vector<ProfilePoint>& profile, int segments) {
    std::vector<float> arcLength(profile.size(), 0.0f);
    for (std::size_t i = 1; i < profile.size(); ++i)
        arcLength[i] = arcLength[i - 1] + std::hypot(profile[i].radius - profile[i - 1].radius,
                                                     profile[i].height - profile[i - 1].height);
    Mesh mesh;
    for (std::size_t i = 0; i < profile.size(); ++i) {
        const ProfilePoint& point = profile[i];
        for (int j = 0; j <= segments; ++j) {
            const float u = float(j) / float(segments);
            const float angle = (u - 0.5f) * 2.0f * kPi;
            const float s = std::sin(angle), c = std::cos(angle);
            mesh.vertices.push_back(
                {{point.radius * s, point.height, point.radius * c},
                 glm::normalize(glm::vec3(point.normal.x * s, point.normal.y, point.normal.x * c)),
                 {u, arcLength[i] / arcLength.back()}});
        }
    }
    addGridTriangles(mesh, 0, int(profile.size()) - 1, segments);
    return mesh;
}

void appendArc(std::vector<ProfilePoint>& profile, glm::vec2 centre, float radius, float fromAngle,
               float toAngle, int steps) {
    for (int i = 0; i <= steps; ++i) {
        const float polar = fromAngle + (toAngle - fromAngle) * float(i) / float(steps);
        // Exactly on the axis at the poles (float sin(pi) is not 0), so that their triangles
        // are recognised as degenerate.
        const float radial = i == 0 && fromAngle == 0.0f      ? 0.0f
                             : (i == steps && toAngle == kPi) ? 0.0f
                                                              : std::sin(polar);
        const glm::vec2 normal(radial, std::cos(polar));
        profile.push_back({centre.x + radius * normal.x, centre.y + radius * normal.y, normal});
    }
}

// A flat ring or cylinder from `from` to `to` with one normal, subdivided so that the light
// varies smoothly across it; the ends repeat the neighbours' points as creases.
void appendFlat(std::vector<ProfilePoint>& profile, glm::vec2 from, glm::vec2 to, glm::vec2 normal,
                int steps) {
    for (int i = 0; i <= steps; ++i) {
        const glm::vec2 point = from + (to - from) * (float(i) / float(steps));
        profile.push_back({point.x, point.y, normal});
    }
}

// The point on the (p, q) torus knot's centre line at parameter t in [0, 2 pi).
glm::vec3 torusKnotCentre(float t) {
    constexpr float p = 2.0f, q = 3.0f;
    const float ring = 2.0f + std::cos(q * t);
    return {ring * std::cos(p * t), ring * std::sin(p * t), -std::sin(q * t)};
}

}  // namespace

std::string_view toString(BuiltInMesh mesh) {
    switch (mesh) {
        case BuiltInMesh::Sphere:
            return "sphere";
        case BuiltInMesh::ShaderBall:
            return "shaderball";
        case BuiltInMesh::TorusKnot:
            return "knot";
    }
    return "sphere";
}

std::optional<BuiltInMesh> parseBuiltInMesh(std::string_view name) {
    for (BuiltInMesh mesh : {BuiltInMesh::Sphere, BuiltInMesh::ShaderBall, BuiltInMesh::TorusKnot})
        if (name == toString(mesh)) return mesh;
    return std::nullopt;
}

Mesh makeSphereMesh(int segments, int rings) {
    std::vector<ProfilePoint> profile;
    appendArc(profile, {0.0f, 0.0f}, 1.0f, 0.0f, kPi, rings);
    return makeLathe(profile, segments);
}

Mesh makeShaderBallMesh() {
    // Top to bottom: the ball, its flat underside, the neck, the pedestal's top, side and base.
    const float ballRadius = 0.8f, ballCentre = 0.35f, ballEnd = 0.84f * kPi;
    const glm::vec2 ballBottom(ballRadius * std::sin(ballEnd),
                               ballCentre + ballRadius * std::cos(ballEnd));
    const float neckRadius = 0.22f, pedestalTop = -0.62f, pedestalRadius = 0.75f,
                pedestalBottom = -0.8f;
    std::vector<ProfilePoint> profile;
    appendArc(profile, {0.0f, ballCentre}, ballRadius, 0.0f, ballEnd, 96);
    appendFlat(profile, ballBottom, {neckRadius, ballBottom.y}, {0.0f, -1.0f}, 2);
    appendFlat(profile, {neckRadius, ballBottom.y}, {neckRadius, pedestalTop}, {1.0f, 0.0f}, 4);
    appendFlat(profile, {neckRadius, pedestalTop}, {pedestalRadius, pedestalTop}, {0.0f, 1.0f}, 4);
    appendFlat(profile, {pedestalRadius, pedestalTop}, {pedestalRadius, pedestalBottom},
               {1.0f, 0.0f}, 2);
    appendFlat(profile, {pedestalRadius, pedestalBottom}, {0.0f, pedestalBottom}, {0.0f, -1.0f}, 2);
    Mesh mesh = makeLathe(profile, 112);
    fitToUnitSphere(mesh);
    return mesh;
}

Mesh makeTorusKnotMesh() {
    constexpr int alongCurve = 400, aroundTube = 32;
    constexpr float tubeRadius = 0.45f;
    Mesh mesh;
    for (int i = 0; i <= alongCurve; ++i) {
        const float t = 2.0f * kPi * float(i) / float(alongCurve);
        // A frame that turns with the curve: tangent, and a normal from the sum of two close
        // points (they lie on the same side of the knot's centre).
        const glm::vec3 here = torusKnotCentre(t), ahead = torusKnotCentre(t + 0.01f);
        const glm::vec3 tangent = glm::normalize(ahead - here);
        const glm::vec3 binormal = glm::normalize(glm::cross(tangent, ahead + here));
        const glm::vec3 normal = glm::cross(binormal, tangent);
        for (int j = 0; j <= aroundTube; ++j) {
            const float angle = 2.0f * kPi * float(j) / float(aroundTube);
            const glm::vec3 outward = std::cos(angle) * normal + std::sin(angle) * binormal;
            mesh.vertices.push_back({here + tubeRadius * outward,
                                     outward,
                                     {float(i) / float(alongCurve), float(j) / float(aroundTube)}});
        }
    }
    addGridTriangles(mesh, 0, alongCurve, aroundTube);
    fitToUnitSphere(mesh);
    return mesh;
}

Mesh makeBuiltInMesh(BuiltInMesh mesh) {
    switch (mesh) {
        case BuiltInMesh::Sphere:
            return makeSphereMesh();
        case BuiltInMesh::ShaderBall:
            return makeShaderBallMesh();
        case BuiltInMesh::TorusKnot:
            return makeTorusKnotMesh();
    }
    return makeSphereMesh();
}

}  // namespace matevo
