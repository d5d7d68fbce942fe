#pragma once
// The viewer's "Materials" panel: every material of the scene under its own tree node,
// with its type, colour and the parameters its type has, edited live, a principled material's
// textures (thumbnail, source, size, colour space; replace or remove); and "Save scene as".
// It edits the session's scene model and flags the change; the session re-sends the materials to
// the renderer (PathTracer::setMaterials, which recompiles nothing).

#include <ptview/gl/GlObjects.h>
#include <ptview/session/ViewerSession.h>

#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ptview {

// The material as another type, the way the panel's type combo changes it: colour, emission and
// shared parameters carry over, a parameter new to the type gets a usable value.
Material retypedMaterial(const Material& material, MaterialType type);

class MaterialsPanel {
public:
    // Draws the panel's controls into the current window (the viewer's sidebar); an edit flags
    // ViewerModel::kMaterialsChanged. A successful save makes the saved file the scene's file;
    // one that would replace another existing file asks first.
    void draw(ViewerSession& session);
    // Opens that material's node (and scrolls to it) the next time the panel is drawn.
    void openMaterial(std::size_t index) { materialToOpen_ = index; }

private:
    // An emitter's radiance shown as a colour in [0, 1] times a strength, since radiance goes
    // above 1. Kept between frames so that dimming the colour does not renormalize it under the
    // user's mouse; rebuilt from the radiance whenever the two disagree.
    struct EmitterControls {
        glm::vec3 color{1.0f};
        float strength = 0.0f;
    };

    bool drawMaterial(Material& material, EmitterControls& emitter);
    // A principled material's texture inputs: a thumbnail, the source, size and colour space of
    // each, a path field with Load, and Remove. Returns whether a texture changed (which may need
    // another program: the session uploads the scene again).
    bool drawTextures(Scene& scene, Material& material, std::size_t index);
    // A small GL texture of the image for ImGui::Image, made once per image and channel: the
    // image as stored (channel -1), or one channel as grey.
    GLuint thumbnail(const std::shared_ptr<const TextureImage>& image, int channel);
    void save(ViewerSession& session);
    void saveTo(ViewerSession& session, const std::string& path);

    std::vector<EmitterControls> emitters_; // one per material, used by emitters only
    // Thumbnails by image and channel; the entry holds the image, so its address is not reused
    // while cached.
    std::map<std::pair<const TextureImage*, int>, std::pair<std::shared_ptr<const TextureImage>, GlTexture>> thumbnails_;
    // The path typed into each (material, input)'s field, and the last Load's error there.
    std::map<std::pair<std::size_t, int>, std::string> texturePaths_;
    std::map<std::pair<std::size_t, int>, std::string> textureErrors_;
    std::optional<std::size_t> materialToOpen_;
    std::string saveStatus_; // the outcome of the last save, shown under the button
    bool saveFailed_ = false;
};

} // namespace ptview
