#include <ptview/scene/MeshTangents.h>

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace ptview {
namespace {

// A vertex as normal maps see it: corners that share position, normal and texture coordinate
// share a tangent. Corners without a normal are never shared (their normal is the face's).
struct VertexKey {
    std::uint32_t position;
    std::int32_t normal;
    std::int32_t texcoord;
    bool operator==(const VertexKey& o) const {
        return position == o.position && normal == o.normal && texcoord == o.texcoord;
    }
};

struct VertexKeyHash {
    std::size_t operator()(const VertexKey& k) const {
        std::uint64_t h = k.position;
        h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.normal);
        h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.texcoord);
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

struct TangentSum {
    glm::dvec3 dPdu{0.0};
    glm::dvec3 dPdv{0.0};
};

// Any unit vector perpendicular to unit n (Duff et al. 2017, as shaders/shading_frame.glsl).
glm::dvec3 anyPerpendicular(glm::dvec3 n) {
    double s = n.z >= 0.0 ? 1.0 : -1.0;
    double a = -1.0 / (s + n.z);
    return {1.0 + s * n.x * n.x * a, s * n.x * n.y * a, -s * n.x};
}

// The frame at a corner of normal n from summed derivatives: tangent = dP/du without its part
// along n, w the sign that makes w cross(n, tangent) point up the image (along -dP/dv).
glm::vec4 orthonormalTangent(glm::dvec3 n, const TangentSum& sum) {
    glm::dvec3 t = sum.dPdu - n * glm::dot(n, sum.dPdu);
    double length = glm::length(t);
    if (!(length > 1e-20 * glm::length(sum.dPdu)) || !std::isfinite(length)) return glm::vec4(glm::vec3(anyPerpendicular(n)), 1.0f);
    t /= length;
    double w = glm::dot(glm::cross(n, t), -sum.dPdv) < 0.0 ? -1.0 : 1.0;
    return glm::vec4(glm::vec3(t), static_cast<float>(w));
}

} // namespace

std::vector<std::array<glm::vec4, 3>> meshCornerTangents(const TriangleMesh& mesh) {
    const std::size_t count = mesh.triangles.size();
    std::vector<std::array<glm::vec4, 3>> result(count);
    std::vector<TangentSum> faceSums(count);
    std::vector<glm::dvec3> faceNormals(count);
    std::unordered_map<VertexKey, TangentSum, VertexKeyHash> vertexSums;

    auto fromFile = [&](const MeshTriangle& t, int k) { return t.tangent[static_cast<std::size_t>(k)] >= 0; };
    for (std::size_t i = 0; i < count; ++i) {
        const MeshTriangle& triangle = mesh.triangles[i];
        glm::dvec3 p0(mesh.positions[triangle.position[0]]);
        glm::dvec3 e1 = glm::dvec3(mesh.positions[triangle.position[1]]) - p0;
        glm::dvec3 e2 = glm::dvec3(mesh.positions[triangle.position[2]]) - p0;
        glm::dvec3 faceNormal = glm::cross(e1, e2);
        double area = glm::length(faceNormal);
        faceNormals[i] = area > 0.0 ? faceNormal / area : glm::dvec3(0.0, 0.0, 1.0);
        if (fromFile(triangle, 0) && fromFile(triangle, 1) && fromFile(triangle, 2)) continue;
        if (triangle.texcoord[0] < 0 || triangle.texcoord[1] < 0 || triangle.texcoord[2] < 0) continue;
        glm::dvec2 uv0(mesh.texcoords[static_cast<std::size_t>(triangle.texcoord[0])]);
        glm::dvec2 d1 = glm::dvec2(mesh.texcoords[static_cast<std::size_t>(triangle.texcoord[1])]) - uv0;
        glm::dvec2 d2 = glm::dvec2(mesh.texcoords[static_cast<std::size_t>(triangle.texcoord[2])]) - uv0;
        // Solve e1 = d1.x dP/du + d1.y dP/dv, e2 = d2.x dP/du + d2.y dP/dv.
        double det = d1.x * d2.y - d2.x * d1.y;
        if (det == 0.0 || !std::isfinite(det)) continue;
        TangentSum face{(e1 * d2.y - e2 * d1.y) / det, (e2 * d1.x - e1 * d2.x) / det};
        if (!std::isfinite(glm::length(face.dPdu)) || !std::isfinite(glm::length(face.dPdv))) continue;
        faceSums[i] = face;
        for (int k = 0; k < 3; ++k) {
            if (triangle.normal[static_cast<std::size_t>(k)] < 0) continue;
            TangentSum& sum = vertexSums[VertexKey{triangle.position[static_cast<std::size_t>(k)],
                                                   triangle.normal[static_cast<std::size_t>(k)],
                                                   triangle.texcoord[static_cast<std::size_t>(k)]}];
            sum.dPdu += face.dPdu;
            sum.dPdv += face.dPdv;
        }
    }

    for (std::size_t i = 0; i < count; ++i) {
        const MeshTriangle& triangle = mesh.triangles[i];
        for (int k = 0; k < 3; ++k) {
            const auto corner = static_cast<std::size_t>(k);
            if (fromFile(triangle, k)) {
                result[i][corner] = mesh.tangents[static_cast<std::size_t>(triangle.tangent[corner])];
                continue;
            }
            if (triangle.normal[corner] < 0) {
                result[i][corner] = orthonormalTangent(faceNormals[i], faceSums[i]);
                continue;
            }
            glm::dvec3 n(mesh.normals[static_cast<std::size_t>(triangle.normal[corner])]);
            auto found = triangle.texcoord[corner] < 0
                             ? vertexSums.end()
                             : vertexSums.find(VertexKey{triangle.position[corner], triangle.normal[corner], triangle.texcoord[corner]});
            result[i][corner] = orthonormalTangent(n, found == vertexSums.end() ? TangentSum{} : found->second);
        }
    }
    return result;
}

} // namespace ptview
