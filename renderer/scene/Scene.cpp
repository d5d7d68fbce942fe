// The scene model's own geometry: rotations, transforms and what a transform does to a shape.
// Nothing here reads or writes a file; the loader checks a transform's terms before it bakes one.

#include <ptview/scene/Scene.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace ptview {

namespace {
bool sameSlot(const TextureSlot& a, const TextureSlot& b) {
    return a.texture == b.texture && a.scale == b.scale && a.offset == b.offset;
}
} // namespace

bool sameMaterial(const Material& a, const Material& b) {
    return a.name == b.name && a.type == b.type && a.color == b.color && a.radiance == b.radiance && a.ior == b.ior &&
           a.roughness == b.roughness && a.metallic == b.metallic && a.transmission == b.transmission &&
           a.alpha == b.alpha && a.alphaMode == b.alphaMode && a.alphaCutoff == b.alphaCutoff &&
           a.normalScale == b.normalScale && sameSlot(a.baseColorTexture, b.baseColorTexture) &&
           sameSlot(a.roughnessTexture, b.roughnessTexture) && sameSlot(a.metallicTexture, b.metallicTexture) &&
           sameSlot(a.normalTexture, b.normalTexture) && sameSlot(a.emissionTexture, b.emissionTexture) &&
           a.sigmaA == b.sigmaA && a.sigmaS == b.sigmaS && a.g == b.g && a.hasInterior == b.hasInterior &&
           a.importedFrom == b.importedFrom;
}

bool sameLight(const Light& a, const Light& b) {
    return a.name == b.name && a.type == b.type && a.position == b.position && a.intensity == b.intensity &&
           a.direction == b.direction && a.innerAngleDeg == b.innerAngleDeg && a.outerAngleDeg == b.outerAngleDeg;
}

glm::mat4 Transform::objectToWorld() const {
    if (matrix) return *matrix;
    glm::mat4 matrix(rotationMatrix(rotationAxis, rotationDeg) * glm::mat3(glm::scale(glm::mat4(1.0f), scale)));
    matrix[3] = glm::vec4(translate, 1.0f);
    return matrix;
}

float defaultFocusDistance(const CameraDesc& camera) {
    // Two coordinates within the scene's extent can be farther apart than the extent itself.
    return std::min(glm::length(camera.target - camera.eye), kMaxSceneExtent);
}

CameraFrame cameraFrame(const CameraDesc& camera) {
    CameraFrame frame;
    frame.forward = glm::normalize(camera.target - camera.eye);
    float upLength = glm::length(camera.up);
    frame.worldUp = upLength > 0.0f ? camera.up / upLength : glm::vec3(0.0f, 1.0f, 0.0f);
    glm::vec3 right = glm::cross(frame.forward, frame.worldUp);
    if (glm::length(right) < 1e-6f) {
        // Looking along up: any axis orthogonal to forward will do; cross it with the world
        // axis it is least aligned with so the cross product is well conditioned.
        glm::vec3 a = glm::abs(frame.forward);
        glm::vec3 axis = a.x <= a.y && a.x <= a.z ? glm::vec3(1, 0, 0)
                       : a.y <= a.z              ? glm::vec3(0, 1, 0)
                                                 : glm::vec3(0, 0, 1);
        right = glm::cross(frame.forward, axis);
    }
    frame.right = glm::normalize(right);
    frame.up = glm::cross(frame.right, frame.forward);
    return frame;
}

glm::mat3 boxRotation(const Shape& box) {
    return rotationMatrix(box.rotationAxis, box.rotationDeg);
}

glm::vec3 unitDirection(glm::dvec3 v) {
    return glm::vec3(v / glm::length(v));
}

glm::mat3 rotationMatrix(glm::vec3 axis, float degrees) {
    // Only scenes built in code can get here with a zero axis; no rotation beats NaNs.
    if (axis == glm::vec3(0.0f))
        return glm::mat3(1.0f);
    glm::vec3 k = unitDirection(axis);
    float angle = glm::radians(degrees);
    float c = std::cos(angle);
    float s = std::sin(angle);
    // Rodrigues: R = c I + s [k]x + (1 - c) k k^T. glm takes columns, so [k]x reads transposed.
    glm::mat3 crossMatrix(0.0f, k.z, -k.y,
                          -k.z, 0.0f, k.x,
                          k.y, -k.x, 0.0f);
    return c * glm::mat3(1.0f) + s * crossMatrix + (1.0f - c) * glm::outerProduct(k, k);
}

bool isUniform(const glm::vec3& scale) {
    return std::abs(scale.x) == std::abs(scale.y) && std::abs(scale.y) == std::abs(scale.z);
}

void bakeTransform(Shape& shape, const Transform& transform) {
    glm::mat3 rotation = rotationMatrix(transform.rotationAxis, transform.rotationDeg);
    glm::mat3 linear = rotation * glm::mat3(glm::scale(glm::mat4(1.0f), transform.scale));
    auto place = [&](glm::vec3 point) { return linear * point + transform.translate; };
    float uniformScale = std::abs(transform.scale.x);
    switch (shape.type) {
    case ShapeType::Sphere:
        shape.center = place(shape.center);
        shape.radius *= uniformScale;
        break;
    case ShapeType::Quad:
        shape.center = place(shape.center);
        shape.u = linear * shape.u;
        shape.v = linear * shape.v;
        break;
    case ShapeType::Disk:
        shape.center = place(shape.center);
        // Under a uniform scale s the inverse transpose is the rotation divided by s, so the normal
        // is turned and, for a mirroring s < 0, flipped. Inverting the matrix instead took s^3,
        // which underflows at s = 1e-30 and made the normal NaN.
        shape.normal = unitDirection(glm::dvec3(rotation * shape.normal) * (transform.scale.x < 0.0f ? -1.0 : 1.0));
        shape.radius *= uniformScale;
        break;
    case ShapeType::Box: {
        shape.center = place(shape.center);
        shape.halfSize *= glm::abs(transform.scale);
        // Compose the rotations and store the result as axis and angle again.
        glm::quat combined = glm::quat_cast(rotation * boxRotation(shape));
        float angle = glm::angle(combined);
        glm::vec3 axis = glm::axis(combined);
        shape.rotationDeg = glm::degrees(angle);
        shape.rotationAxis = glm::length(axis) > 0.0f && angle != 0.0f ? axis : glm::vec3(0.0f, 1.0f, 0.0f);
        break;
    }
    case ShapeType::Mesh:
        break;
    }
}

} // namespace ptview
