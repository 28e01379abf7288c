#include "export/SphereMesh.h"

#include <cmath>
#include <numbers>

namespace matevo {

SphereMesh makeSphereMesh(int segments, int rings) {
    SphereMesh mesh;
    const double pi = std::numbers::pi;
    for (int ring = 0; ring <= rings; ++ring) {
        const double v = double(ring) / rings;
        const double theta = pi * v;
        for (int segment = 0; segment <= segments; ++segment) {
            const double u = double(segment) / segments;
            const double phi = 2.0 * pi * (u - 0.5);  // atan2(x, z) = phi
            mesh.positions.push_back({float(std::sin(theta) * std::sin(phi)),
                                      float(std::cos(theta)),
                                      float(std::sin(theta) * std::cos(phi))});
            mesh.uvs.push_back({float(u), float(v)});
        }
    }
    const int columns = segments + 1;
    for (int ring = 0; ring < rings; ++ring) {
        for (int segment = 0; segment < segments; ++segment) {
            const auto a = std::uint16_t(ring * columns + segment);
            const auto b = std::uint16_t(a + columns);
            // a is above b; a+1 lies towards +u. Seen from outside, with y up and u growing
            // towards the viewer's right, a -> b -> a+1 runs counter-clockwise.
            if (ring != 0) mesh.indices.insert(mesh.indices.end(), {a, b, std::uint16_t(a + 1)});
            if (ring != rings - 1)
                mesh.indices.insert(mesh.indices.end(),
                                    {std::uint16_t(a + 1), b, std::uint16_t(b + 1)});
        }
    }
    return mesh;
}

}  // namespace matevo
