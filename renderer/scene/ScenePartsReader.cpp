#include <ptview/scene/ScenePartsReader.h>

#include <ptview/scene/GltfLoader.h>
#include <ptview/scene/LightSchema.h>
#include <ptview/scene/MaterialReader.h>
#include <ptview/scene/SceneFileReaders.h>
#include <ptview/scene/ShapeSchema.h>

#include <cmath>
#include <cstdio>
#include <map>

namespace ptview::sceneFile {
namespace {

CameraDesc readCamera(const Json& value, const Pointer& at) {
    requireObject(value, at);
    checkKeys(value, at, {"eye", "target", "up", "vfov_deg", "resolution", "aperture_radius", "focus_distance"});
    CameraDesc camera;
    camera.eye = readPosition(requireKey(value, at, "eye"), at / "eye");
    camera.target = readPosition(requireKey(value, at, "target"), at / "target");
    if (camera.target == camera.eye)
        fail(at / "target", "must differ from eye");
    if (const Json* up = optionalKey(value, "up")) {
        camera.up = readNonzeroVec3(*up, at / "up");
        if (areParallel(camera.up, camera.target - camera.eye))
            fail(at / "up", "must not be parallel to the view direction (target - eye)");
    } else if (areParallel(camera.up, camera.target - camera.eye)) {
        fail(at / "up", "missing, and the default [0, 1, 0] is parallel to the view direction");
    }
    camera.vfovDeg = readInRange(requireKey(value, at, "vfov_deg"), at / "vfov_deg", ranges::kVerticalFov);
    camera.resolution = readResolution(requireKey(value, at, "resolution"), at / "resolution");
    if (const Json* aperture = optionalKey(value, "aperture_radius"))
        camera.apertureRadius = readInRange(*aperture, at / "aperture_radius", ranges::kApertureRadius);
    const Json* focus = optionalKey(value, "focus_distance");
    camera.focusDistance = focus ? readInRange(*focus, at / "focus_distance", ranges::kFocusDistance)
                                 : defaultFocusDistance(camera);
    return camera;
}

// Either a constant "color" or a "map" (scaled by "intensity", turned by "rotation_deg"), never
// both: a colour beside a map would be silently unused. The map's path stays as written here;
// parseScene resolves it against the file's directory.
void readEnvironment(const Json& value, const Pointer& at, Scene& scene) {
    requireObject(value, at);
    checkKeys(value, at, {"color", "map", "intensity", "rotation_deg"});
    const Json* map = optionalKey(value, "map");
    if (!map) {
        for (const char* key : {"intensity", "rotation_deg"})
            if (optionalKey(value, key)) fail(at / key, "only allowed with \"map\"");
        if (!optionalKey(value, "color")) fail(at / "color", "missing required key (or give \"map\")");
        scene.environment = readVec3InRange(value.at("color"), at / "color", ranges::kRadiance);
        return;
    }
    if (optionalKey(value, "color")) fail(at / "color", "not allowed with \"map\" (the map gives the radiance)");
    std::string path = readString(*map, at / "map");
    if (path.empty()) fail(at / "map", "expected a file name, got an empty string");
    scene.environmentMap = std::filesystem::u8path(path);
    if (const Json* intensity = optionalKey(value, "intensity"))
        scene.environmentIntensity = readInRange(*intensity, at / "intensity", ranges::kEnvironmentIntensity);
    if (const Json* rotation = optionalKey(value, "rotation_deg"))
        scene.environmentRotationDeg = readInRange(*rotation, at / "rotation_deg", ranges::kEnvironmentRotation);
}

// "rotation": {"axis": [x, y, z], "degrees": d}, as boxes and transforms write it.
void readRotation(const Json& value, const Pointer& at, glm::vec3& axis, float& degrees) {
    requireObject(value, at);
    checkKeys(value, at, {"axis", "degrees"});
    axis = readNonzeroVec3(requireKey(value, at, "axis"), at / "axis");
    degrees = readNumber(requireKey(value, at, "degrees"), at / "degrees");
}

Transform readTransform(const Json& value, const Pointer& at) {
    requireObject(value, at);
    checkKeys(value, at, {"translate", "rotation", "scale"});
    Transform transform;
    if (const Json* translate = optionalKey(value, "translate"))
        transform.translate = readPosition(*translate, at / "translate");
    if (const Json* rotation = optionalKey(value, "rotation"))
        readRotation(*rotation, at / "rotation", transform.rotationAxis, transform.rotationDeg);
    if (const Json* scale = optionalKey(value, "scale")) {
        // One number scales uniformly; zero would flatten the object to nothing.
        transform.scale = scale->is_number() ? glm::vec3(readNumber(*scale, at / "scale"))
                                             : readVec3(*scale, at / "scale", [](float c) { return c != 0.0f; },
                                                        "a nonzero number");
        if (transform.scale.x == 0.0f) fail(at / "scale", "expected a nonzero number");
    }
    return transform;
}

// Spheres, disks and rotated boxes stay what they are only under a uniform scale, and boxes only
// under a positive one, so anything else is an error, not a silent change (bakeTransform's terms).
void checkTransformable(const Shape& shape, const Transform& transform, const Pointer& at) {
    switch (shape.type) {
    case ShapeType::Sphere:
        if (!isUniform(transform.scale)) fail(at / "scale", "a sphere takes only a uniform scale");
        break;
    case ShapeType::Disk:
        if (!isUniform(transform.scale)) fail(at / "scale", "a disk takes only a uniform scale");
        break;
    case ShapeType::Box:
        if (!isUniform(transform.scale) && shape.rotationDeg != 0.0f)
            fail(at / "scale", "a rotated box takes only a uniform scale (a sheared box is not a box)");
        if (transform.scale.x < 0.0f || transform.scale.y < 0.0f || transform.scale.z < 0.0f)
            fail(at / "scale", "a box takes only a positive scale");
        break;
    case ShapeType::Quad:
    case ShapeType::Mesh:
        break;
    }
}

// The bounds hold for what is stored, after the transform: a radius of 1e8 scaled by 100 is as far
// out of range as one of 1e10 written so. The message names the transformed value.
void checkTransformedShape(const Shape& shape, const Pointer& at) {
    auto refuse = [&](const std::string& what, double value) {
        fail(at / "transform", "gives a " + what + " of " + boundText(static_cast<float>(std::min(value, 3.4e38))) +
                                   ", above " + boundText(kMaxExtent) + " (metres)");
    };
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(shape.center[i]) <= kMaxExtent)) refuse("centre coordinate", std::abs(shape.center[i]));
    switch (shape.type) {
    case ShapeType::Sphere:
    case ShapeType::Disk:
        if (!(shape.radius <= kMaxExtent)) refuse("radius", shape.radius);
        break;
    case ShapeType::Quad:
        if (!(glm::length(glm::dvec3(shape.u)) <= kMaxExtent)) refuse("length of u", glm::length(glm::dvec3(shape.u)));
        if (!(glm::length(glm::dvec3(shape.v)) <= kMaxExtent)) refuse("length of v", glm::length(glm::dvec3(shape.v)));
        break;
    case ShapeType::Box:
        for (int i = 0; i < 3; ++i)
            if (!(shape.halfSize[i] <= kMaxExtent)) refuse("half size", shape.halfSize[i]);
        break;
    case ShapeType::Mesh:
        break;
    }
}

// What a shape and a light begin with: an object whose "type" names a schema of `schemas`, keys
// only of that type (the first problem reported as before), and a name (TYPE INDEX when none).
template <typename Schema, std::size_t N>
const Schema* readTypeAndName(const Json& value, const Pointer& at, std::size_t index, const Schema (&schemas)[N],
                              const char* noun, const std::vector<const char*>& anyTypeKeys,
                              std::vector<const char*> (*keysOf)(const Schema&), std::string& name) {
    requireObject(value, at);
    requireType(value, at, anyTypeKeys);
    std::string type = readString(value.at("type"), at / "type");
    const Schema* schema = findSchemaNamed(schemas, type);
    if (!schema)
        fail(at / "type", std::string("unknown ") + noun + " type \"" + type + "\" (expected " + schemaNameList(schemas) + ")");
    checkKeys(value, at, keysOf(*schema));
    const Json* given = optionalKey(value, "name");
    name = given ? readString(*given, at / "name") : type + " " + std::to_string(index);
    return schema;
}

Shape readShape(const Json& value, const Pointer& at, std::size_t index,
                const std::vector<Material>& materials, const std::map<std::string, int>& meshes,
                std::vector<MeshMaterialRequest>& meshRequests) {
    Shape shape;
    const ShapeSchema* schema = readTypeAndName(value, at, index, kShapeSchemas, "shape", anyShapeKeys(), shapeKeys, shape.name);
    shape.type = schema->type;
    const Json* transform = optionalKey(value, "transform");
    if (transform) shape.transform = readTransform(*transform, at / "transform");

    if (shape.type == ShapeType::Mesh) {
        std::string meshName = readString(requireKey(value, at, "mesh"), at / "mesh");
        auto mesh = meshes.find(meshName);
        if (mesh == meshes.end()) fail(at / "mesh", "unknown mesh \"" + meshName + "\" (declare it under \"meshes\")");
        shape.mesh = mesh->second;
        MeshMaterialRequest request{index, at, std::nullopt, {}};
        if (const Json* material = optionalKey(value, "material")) {
            request.material = readString(*material, at / "material");
            if (findMaterial(materials, *request.material) < 0)
                fail(at / "material", "unknown material \"" + *request.material + "\"");
        }
        if (const Json* bySlot = optionalKey(value, "materials")) {
            requireObject(*bySlot, at / "materials");
            for (auto it = bySlot->begin(); it != bySlot->end(); ++it) {
                std::string target = readString(it.value(), at / "materials" / it.key());
                if (findMaterial(materials, target) < 0)
                    fail(at / "materials" / it.key(), "unknown material \"" + target + "\"");
                request.bySlot.emplace_back(it.key(), target);
            }
        }
        meshRequests.push_back(std::move(request));
        return shape;
    }

    std::string materialName = readString(requireKey(value, at, "material"), at / "material");
    shape.material = findMaterial(materials, materialName);
    if (shape.material < 0)
        fail(at / "material", "unknown material \"" + materialName + "\"");
    shape.center = readPosition(requireKey(value, at, "center"), at / "center");

    switch (shape.type) {
    case ShapeType::Sphere:
        shape.radius = readLength(requireKey(value, at, "radius"), at / "radius");
        break;
    case ShapeType::Quad:
        shape.u = readEdge(requireKey(value, at, "u"), at / "u");
        shape.v = readEdge(requireKey(value, at, "v"), at / "v");
        // A degenerate quad has no area and no normal.
        if (areParallel(shape.u, shape.v))
            fail(at / "v", "must not be parallel to u");
        break;
    case ShapeType::Box:
        shape.halfSize = readVec3(requireKey(value, at, "half_size"), at / "half_size",
                                  [](float c) { return c > 0.0f && c <= kMaxExtent; },
                                  ("a positive number at most " + boundText(kMaxExtent) + " (metres)").c_str());
        if (const Json* rotation = optionalKey(value, "rotation"))
            readRotation(*rotation, at / "rotation", shape.rotationAxis, shape.rotationDeg);
        break;
    case ShapeType::Disk:
        shape.normal = readDirection(requireKey(value, at, "normal"), at / "normal");
        shape.radius = readLength(requireKey(value, at, "radius"), at / "radius");
        break;
    case ShapeType::Mesh:
        break;
    }
    if (transform) {
        checkTransformable(shape, shape.transform, at / "transform");
        bakeTransform(shape, shape.transform);
        shape.transform = Transform{};
        checkTransformedShape(shape, at);
    }
    return shape;
}

// A value the file left out, for messages that mention it.
std::string defaultText(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g, the default", static_cast<double>(value));
    return text;
}

} // namespace

Light readLight(const Json& value, const Pointer& at, std::size_t index) {
    Light light;
    const LightSchema* schema = readTypeAndName(value, at, index, kLightSchemas, "light", anyLightKeys(), lightKeys, light.name);
    light.type = schema->type;
    if (light.type != LightType::Directional)
        light.position = readPosition(requireKey(value, at, "position"), at / "position");
    // A directional light's "intensity" is the irradiance it gives a surface facing it (Scene.h).
    light.intensity = readVec3InRange(requireKey(value, at, "intensity"), at / "intensity", ranges::kIntensity);
    if (light.type != LightType::Point)
        light.direction = readDirection(requireKey(value, at, "direction"), at / "direction");
    if (light.type == LightType::Spot) {
        const Json* inner = optionalKey(value, "inner_deg");
        const Json* outer = optionalKey(value, "outer_deg");
        if (inner) light.innerAngleDeg = readInRange(*inner, at / "inner_deg", ranges::kSpotConeAngle);
        if (outer) light.outerAngleDeg = readInRange(*outer, at / "outer_deg", ranges::kSpotConeAngle);
        bool ordered = ranges::coneAnglesOrdered(light.innerAngleDeg, light.outerAngleDeg);
        // Blame an angle the file gives, the inner one when it gives both.
        if (!ordered && inner)
            fail(at / "inner_deg", "must not exceed outer_deg (" +
                                       (outer ? outer->dump() : defaultText(light.outerAngleDeg)) + ")");
        if (!ordered)
            fail(at / "outer_deg", "must not be less than inner_deg (" + defaultText(light.innerAngleDeg) + ")");
    }
    return light;
}

namespace {

// "gltf": [{"file": "helmet.glb", "transform": {...}, "materials": {...}}]: glTF files placed in
// the scene, read once the rest is, and their materials' overrides (resolveImports).
void readImports(const Json& value, const Pointer& at, SceneDraft& draft) {
    if (!value.is_array()) fail(at, "expected an array, got " + describe(value));
    for (std::size_t i = 0; i < value.size(); ++i) {
        const Pointer entryAt = at / i;
        requireObject(value[i], entryAt);
        checkKeys(value[i], entryAt, {"file", "transform", "materials", "lights"});
        SceneImport entry;
        std::string file = readString(requireKey(value[i], entryAt, "file"), entryAt / "file");
        if (!isGltfFile(std::filesystem::u8path(file)))
            fail(entryAt / "file", "expected a .gltf or .glb file, got \"" + file + "\"");
        entry.file = std::filesystem::u8path(file);
        if (const Json* transform = optionalKey(value[i], "transform"))
            entry.transform = readTransform(*transform, entryAt / "transform");
        const Json* overrides = optionalKey(value[i], "materials");
        if (overrides) requireObject(*overrides, entryAt / "materials");
        draft.scene.imports.push_back(entry);
        draft.importPlaces.push_back(entryAt / "file");
        draft.importOverrides.push_back(overrides);
        const Json* lightOverrides = optionalKey(value[i], "lights");
        if (lightOverrides) requireObject(*lightOverrides, entryAt / "lights");
        draft.importLightOverrides.push_back(lightOverrides);
    }
}

} // namespace

SceneDraft readScene(const Json& root) {
    const Pointer top;
    if (!root.is_object())
        fail(top, "expected an object at the top level, got " + describe(root));
    checkKeys(root, top, {"camera", "environment", "materials", "meshes", "shapes", "lights", "gltf"});

    SceneDraft draft;
    Scene& scene = draft.scene;
    scene.camera = readCamera(requireKey(root, top, "camera"), top / "camera");
    if (const Json* environment = optionalKey(root, "environment"))
        readEnvironment(*environment, top / "environment", scene);

    const Pointer materialsAt = top / "materials";
    const Json& materials = requireObject(requireKey(root, top, "materials"), materialsAt);
    for (auto it = materials.begin(); it != materials.end(); ++it)
        scene.materials.push_back(
            readMaterial(it.key(), it.value(), materialsAt / it.key(), scene.materials.size(), draft.textureRequests));

    std::map<std::string, int> meshIndex;
    if (const Json* meshes = optionalKey(root, "meshes")) {
        const Pointer meshesAt = top / "meshes";
        requireObject(*meshes, meshesAt);
        for (auto it = meshes->begin(); it != meshes->end(); ++it) {
            Pointer at = meshesAt / it.key();
            requireObject(it.value(), at);
            checkKeys(it.value(), at, {"file"});
            std::string file = readString(requireKey(it.value(), at, "file"), at / "file");
            if (file.empty()) fail(at / "file", "expected a file name, got an empty string");
            meshIndex[it.key()] = static_cast<int>(scene.meshes.size());
            scene.meshes.push_back(SceneMesh{it.key(), std::filesystem::u8path(file), nullptr});
            draft.meshPlaces.push_back(at / "file");
        }
    }

    const Pointer shapesAt = top / "shapes";
    const Json& shapes = requireKey(root, top, "shapes");
    if (!shapes.is_array())
        fail(shapesAt, "expected an array, got " + describe(shapes));
    for (std::size_t i = 0; i < shapes.size(); ++i)
        scene.shapes.push_back(readShape(shapes[i], shapesAt / i, i, scene.materials, meshIndex, draft.meshRequests));

    if (const Json* lights = optionalKey(root, "lights")) {
        const Pointer lightsAt = top / "lights";
        if (!lights->is_array())
            fail(lightsAt, "expected an array, got " + describe(*lights));
        for (std::size_t i = 0; i < lights->size(); ++i)
            scene.lights.push_back(readLight((*lights)[i], lightsAt / i, i));
    }
    if (const Json* gltf = optionalKey(root, "gltf")) readImports(*gltf, top / "gltf", draft);
    return draft;
}

} // namespace ptview::sceneFile
