#include <ptview/gpu/GpuMeshes.h>

#include <ptview/geometry/WideBvh.h>
#include <ptview/gpudata/BvhNodePacking.h>
#include <ptview/scene/MeshTangents.h>

#include <algorithm>
#include <chrono>
#include <future>
#include <stdexcept>
#include <string>

namespace ptview {
namespace {

// Exact in a float up to 2^24: more is refused rather than silently rounded.
float exactFloat(std::size_t value) {
    if (value >= (std::size_t(1) << 24))
        throw std::runtime_error("the meshes need index " + std::to_string(value) +
                                 ", beyond the 2^24 a float stores exactly (too many triangles)");
    return static_cast<float>(value);
}

// Rows of the upper 3x4 of a matrix: row r holds (m[0][r], m[1][r], m[2][r], m[3][r]), so that
// dot(row, vec4(p, 1)) is the r-th coordinate of m * p.
void appendRows(const glm::mat4& m, std::vector<glm::vec4>& out) {
    for (int r = 0; r < 3; ++r) out.emplace_back(m[0][r], m[1][r], m[2][r], m[3][r]);
}

// The meshes, in the order of Scene::meshes, that some shape covers with a normal-mapped material.
std::vector<const TriangleMesh*> meshesWithNormalMaps(const Scene& scene) {
    std::vector<const TriangleMesh*> meshes;
    for (const Shape& shape : scene.shapes) {
        if (shape.type != ShapeType::Mesh) continue;
        const TriangleMesh* data = scene.meshes[static_cast<std::size_t>(shape.mesh)].data.get();
        bool normalMapped = false;
        for (int material : shape.slotMaterials)
            normalMapped = normalMapped || scene.materials[static_cast<std::size_t>(material)].normalTexture.used();
        if (normalMapped && std::find(meshes.begin(), meshes.end(), data) == meshes.end()) meshes.push_back(data);
    }
    std::sort(meshes.begin(), meshes.end());
    return meshes;
}

} // namespace

const char* const GpuMeshes::kSamplerNames[kTextureCount] = {"uMeshNodes", "uMeshTriangles", "uMeshInstances"};

GpuMeshes::BuiltMesh GpuMeshes::buildMesh(const TriangleMesh& mesh, bool withTangents, double& tangentSeconds) {
    std::vector<Aabb> bounds(mesh.triangles.size());
    std::vector<glm::vec3> centroids(mesh.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        for (std::uint32_t index : mesh.triangles[i].position) bounds[i].extend(mesh.positions[index]);
        centroids[i] = bounds[i].centroid();
    }
    BuiltMesh built;
    const WideBvh bvh = collapseToWideBvh(buildBvh(bounds, centroids));
    // Packing the nodes and making the triangle records are independent: on two cores, one each
    // (a tenth of a second or more each for a million triangles).
    auto packing = std::async(std::launch::async, [&bvh] {
        std::vector<GpuBvhNode> packed;
        packed.reserve(bvh.nodes.size());
        for (const WideBvhNode& node : bvh.nodes) packed.push_back(packBvhNode(node));
        return packed;
    });
    built.triangles.reserve(mesh.triangles.size());
    std::vector<std::array<glm::vec4, 3>> tangents;
    if (withTangents) {
        auto start = std::chrono::steady_clock::now();
        tangents = meshCornerTangents(mesh);
        tangentSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    for (std::uint32_t original : bvh.primitiveOrder) {
        const MeshTriangle& source = mesh.triangles[original];
        GpuTriangle triangle{};
        triangle.p0 = mesh.positions[source.position[0]];
        triangle.p1 = mesh.positions[source.position[1]];
        triangle.p2 = mesh.positions[source.position[2]];
        triangle.materialSlot = static_cast<float>(source.materialSlot);
        glm::vec3 normal[3];
        glm::vec2 uv[3];
        for (int corner = 0; corner < 3; ++corner) {
            normal[corner] = source.normal[corner] >= 0 ? mesh.normals[static_cast<std::size_t>(source.normal[corner])] : glm::vec3(0.0f);
            uv[corner] = source.texcoord[corner] >= 0 ? mesh.texcoords[static_cast<std::size_t>(source.texcoord[corner])] : glm::vec2(0.0f);
        }
        // A triangle with any corner lacking a normal is shaded flat, not with a half-made one.
        if (normal[0] == glm::vec3(0.0f) || normal[1] == glm::vec3(0.0f) || normal[2] == glm::vec3(0.0f))
            normal[0] = normal[1] = normal[2] = glm::vec3(0.0f);
        triangle.n0AndU0 = glm::vec4(normal[0], uv[0].x);
        triangle.n1AndV0 = glm::vec4(normal[1], uv[0].y);
        triangle.n2AndU1 = glm::vec4(normal[2], uv[1].x);
        triangle.v1U2V2 = glm::vec4(uv[1].y, uv[2].x, uv[2].y, 0.0f);
        triangle.tangentTexel = -1.0f;
        if (withTangents) {
            triangle.tangentTexel = exactFloat(built.tangents.size());
            built.tangents.insert(built.tangents.end(), tangents[original].begin(), tangents[original].end());
        }
        built.triangles.push_back(triangle);
        built.bounds.extend(bounds[original]);
    }
    built.nodes = packing.get();
    return built;
}

void GpuMeshes::upload(const Scene& scene) {
    auto start = std::chrono::steady_clock::now();
    withTangents_ = meshesWithNormalMaps(scene);
    lastTangentSeconds_ = 0.0;
    std::map<MeshKey, std::shared_ptr<BuiltMesh>> stillUsed;
    std::vector<std::shared_ptr<const TriangleMesh>> keepAlive;
    for (const Shape& shape : scene.shapes) {
        if (shape.type != ShapeType::Mesh) continue;
        const std::shared_ptr<const TriangleMesh>& data = scene.meshes[static_cast<std::size_t>(shape.mesh)].data;
        MeshKey key{data.get(), std::binary_search(withTangents_.begin(), withTangents_.end(), data.get())};
        if (stillUsed.count(key)) continue;
        auto known = built_.find(key);
        if (known != built_.end()) {
            stillUsed[key] = known->second;
        } else {
            stillUsed[key] = std::make_shared<BuiltMesh>(buildMesh(*data, key.second, lastTangentSeconds_));
        }
        keepAlive.push_back(data);
    }
    built_ = std::move(stillUsed);
    keepAlive_ = std::move(keepAlive);

    // Bottom levels, one after another, then the top level. Only the nodes are copied here; the
    // triangles go from each BuiltMesh straight into the buffer below.
    std::size_t totalTriangles = 0, totalNodes = 0, totalTangents = 0;
    for (const auto& entry : built_) {
        totalTriangles += entry.second->triangles.size();
        totalNodes += entry.second->nodes.size();
        totalTangents += entry.second->tangents.size();
    }
    std::vector<GpuBvhNode> nodes;
    nodes.reserve(totalNodes + 2 * built_.size() + 1); // the top level has about an instance's worth
    std::map<const BuiltMesh*, std::pair<std::uint32_t, std::uint32_t>> placement; // root node, first triangle
    std::uint32_t triangleOffset = 0;
    for (const auto& [key, built] : built_) {
        auto nodeOffset = static_cast<std::uint32_t>(nodes.size());
        placement[built.get()] = {nodeOffset, triangleOffset};
        for (const GpuBvhNode& node : built->nodes) nodes.push_back(placedBvhNode(node, nodeOffset, triangleOffset));
        triangleOffset += static_cast<std::uint32_t>(built->triangles.size());
    }

    struct Candidate {
        MeshInstance instance;
        std::uint32_t root;
        Aabb worldBounds;
    };
    std::vector<Candidate> candidates;
    for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
        const Shape& shape = scene.shapes[s];
        if (shape.type != ShapeType::Mesh) continue;
        const TriangleMesh* data = scene.meshes[static_cast<std::size_t>(shape.mesh)].data.get();
        const BuiltMesh& built = *built_.at(MeshKey{data, std::binary_search(withTangents_.begin(), withTangents_.end(), data)});
        if (built.nodes.empty()) continue; // nothing to hit
        glm::mat4 objectToWorld = shape.transform.objectToWorld();
        auto [root, firstTriangle] = placement.at(&built);
        candidates.push_back(Candidate{MeshInstance{static_cast<int>(s), objectToWorld, &built.triangles, firstTriangle,
                                                    shape.slotMaterials},
                                       root, transformedBounds(built.bounds, objectToWorld)});
    }

    std::vector<Aabb> bounds;
    std::vector<glm::vec3> centroids;
    worldBounds_ = Aabb{};
    for (const Candidate& candidate : candidates) {
        bounds.push_back(candidate.worldBounds);
        centroids.push_back(candidate.worldBounds.centroid());
        worldBounds_.extend(candidate.worldBounds);
    }
    WideBvh topLevel = collapseToWideBvh(buildBvh(bounds, centroids, BvhBuildOptions{1}));
    topLevelRoot_ = topLevel.nodes.empty() ? -1 : static_cast<int>(nodes.size());
    // Instances go in the top level's leaf order, so a leaf's range indexes them directly.
    for (const WideBvhNode& node : topLevel.nodes)
        nodes.push_back(placedBvhNode(packBvhNode(node), static_cast<std::uint32_t>(topLevelRoot_), 0));
    instances_.clear();
    instanceRoots_.clear();
    for (std::uint32_t original : topLevel.primitiveOrder) {
        instances_.push_back(candidates[original].instance);
        instanceRoots_.push_back(candidates[original].root);
    }
    triangleCount_ = totalTriangles;
    lastBuildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    textures_[0].fill(GL_RGBA32UI, 16, nodes);
    // GpuTriangle's layout on the GPU: the first kTrianglePositionTexels texels of every triangle,
    // then the others of every triangle from attributeStart_, then the tangent texels.
    attributeStart_ = static_cast<int>(totalTriangles * kTrianglePositionTexels);
    const std::size_t tangentStart = totalTriangles * kTriangleTexels;
    textures_[1].fillWith<glm::vec4>(GL_RGBA32F, 16, tangentStart + totalTangents, [&](glm::vec4* texels) {
        std::size_t first = 0, tangentOffset = 0;
        for (const auto& entry : built_) {
            const BuiltMesh& built = *entry.second;
            for (std::size_t i = 0; i < built.triangles.size(); ++i) {
                GpuTriangle triangle = built.triangles[i];
                // The tangents' index becomes absolute in the buffer.
                if (triangle.tangentTexel >= 0.0f)
                    triangle.tangentTexel = exactFloat(tangentStart + tangentOffset + static_cast<std::size_t>(triangle.tangentTexel));
                const auto* source = reinterpret_cast<const glm::vec4*>(&triangle);
                std::copy(source, source + kTrianglePositionTexels, texels + (first + i) * kTrianglePositionTexels);
                std::copy(source + kTrianglePositionTexels, source + kTriangleTexels,
                          texels + static_cast<std::size_t>(attributeStart_) + (first + i) * kTriangleAttributeTexels);
            }
            std::copy(built.tangents.begin(), built.tangents.end(), texels + tangentStart + tangentOffset);
            first += built.triangles.size();
            tangentOffset += built.tangents.size();
        }
    });
    gpuBytes_ = textures_[0].bytes() + textures_[1].bytes();
}

bool GpuMeshes::tangentsChanged(const Scene& scene) const {
    return meshesWithNormalMaps(scene) != withTangents_;
}

void GpuMeshes::uploadInstances(const std::vector<std::int32_t>& lightBase) {
    // Per instance its kInstanceTexels; then the material tables, one material index per texel.
    std::vector<glm::vec4> texels;
    std::vector<float> tables;
    for (std::size_t i = 0; i < instances_.size(); ++i) {
        const MeshInstance& instance = instances_[i];
        appendRows(glm::inverse(instance.objectToWorld), texels);
        appendRows(instance.objectToWorld, texels);
        std::int32_t light = i < lightBase.size() ? lightBase[i] : -1;
        texels.emplace_back(exactFloat(instanceRoots_[i]), exactFloat(instance.triangleOffset), exactFloat(tables.size()),
                            light < 0 ? -1.0f : exactFloat(static_cast<std::size_t>(light)));
        texels.emplace_back(0.0f);
        for (int material : instance.slotMaterials) tables.push_back(exactFloat(static_cast<std::size_t>(material)));
    }
    for (float entry : tables) texels.emplace_back(entry, 0.0f, 0.0f, 0.0f);
    textures_[2].fill(GL_RGBA32F, 16, texels);
}

void GpuMeshes::bind(int firstUnit) const {
    for (int i = 0; i < kTextureCount; ++i) textures_[i].bind(firstUnit + i);
}

} // namespace ptview
