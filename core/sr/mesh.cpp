// SPDX-License-Identifier: BSD-3-Clause
#include "core/sr/mesh.hpp"

#include <cmath>
#include <stdexcept>

namespace lc::sr {

TriMesh makeCube(double edge, int n, const Vec3& centre) {
    if (n < 1 || !(edge > 0.0)) throw std::invalid_argument("makeCube: n >= 1, edge > 0");
    TriMesh m;
    const double h = 0.5 * edge;
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign : {-1, 1}) {
            Vec3 normal = Vec3::Zero();
            normal[axis] = sign;
            // (u, v, normal) right-handed so triangles wind counter-clockwise seen from outside.
            Vec3 u = Vec3::Zero(), v = Vec3::Zero();
            u[(axis + 1) % 3] = 1.0;
            v[(axis + 2) % 3] = 1.0;
            if (sign < 0) std::swap(u, v);
            const int base = static_cast<int>(m.positions.size());
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i) {
                    const double a = -h + edge * i / n, b = -h + edge * j / n;
                    m.positions.push_back(centre + h * normal + a * u + b * v);
                    m.normals.push_back(normal);
                }
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const int v00 = base + j * (n + 1) + i, v10 = v00 + 1, v01 = v00 + n + 1, v11 = v01 + 1;
                    m.triangles.push_back({v00, v10, v11});
                    m.triangles.push_back({v00, v11, v01});
                }
        }
    }
    return m;
}

TriMesh makeUvSphere(double radius, int slices, int stacks, const Vec3& centre) {
    if (slices < 3 || stacks < 2 || !(radius > 0.0)) throw std::invalid_argument("makeUvSphere: bad size");
    TriMesh m;
    for (int j = 0; j <= stacks; ++j) {
        const double theta = kPi * j / stacks;
        for (int i = 0; i <= slices; ++i) {
            const double phi = 2.0 * kPi * i / slices;
            const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
            m.positions.push_back(centre + radius * n);
            m.normals.push_back(n);
        }
    }
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const int a = j * (slices + 1) + i, b = a + 1, c = a + slices + 1, d = c + 1;
            // Skip the degenerate triangles at the poles.
            if (j != 0) m.triangles.push_back({a, c, b});
            if (j != stacks - 1) m.triangles.push_back({b, c, d});
        }
    return m;
}

}  // namespace lc::sr
