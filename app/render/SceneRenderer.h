#pragma once
// The 3D view: the 2011 model figure made live. The bone surface, the CT box with its x/y/z
// axes, the X-ray source, the film (textured with the user's DRR) and the ray cone, drawn
// offscreen in the isocenter frame: the CT sits at its offset, the source and film turn with
// azimuth, elevation and rotation. The result is a texture the UI shows.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/Pose.h"
#include "mesh/Mesh.h"
#include "platform/Gl.h"
#include "render/Shader.h"
#include "render/SurfaceItem.h"
#include "state/AppState.h"

namespace fm::app {
struct LoadedScene;
}

namespace fm::render {

struct LineVertex;

// One camera of the real X-ray workspace's 3D view, in the world frame: its source, its film's
// four corners (pixel (0, 0)'s outer corner first, then along the row, ...) and the texture on it.
struct RigCamera {
    glm::dvec3 source{0.0};
    std::array<glm::dvec3, 4> film{};
    GLuint texture = 0;
    std::string name;
};

struct SceneLabel {
    glm::vec2 pixel;  // position in the view, pixels from the top-left
    std::string text;
    glm::vec4 color;
};

class SceneRenderer {
  public:
    SceneRenderer();
    ~SceneRenderer();
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    // Draws into the offscreen texture of the given size (re-created when the size changes).
    // `filmTexture` is the user's DRR (0: a blank film). Restores the default framebuffer.
    // `multisample` false draws straight into the shown texture (fast while interacting).
    // `surfaces` are the bone surfaces to show (one, or one per bone, each in its colour).
    // `slicePlane` (the MRI slice mode): instead of source, film and rays, the slice plane of
    // `pose` where it cuts the volume's box, textured with the user's slice, and the surface
    // translucent so the plane shows through it.
    void draw(const app::LoadedScene* scene, const std::vector<SurfaceItem>& surfaces,
              const Pose& pose, const app::View3d& view, GLuint filmTexture, glm::ivec2 size,
              bool multisample = true, bool slicePlane = false);

    // The workspace's 3D view: each camera (its source, its film textured with its radiograph,
    // the ray cone) and the surfaces at their world poses, framed about `centre` (world mm).
    void drawRig(const std::vector<RigCamera>& cameras, const std::vector<SurfaceItem>& surfaces,
                 const glm::dvec3& centre, const app::View3d& view, glm::ivec2 size,
                 bool multisample = true);

    GLuint texture() const { return resolveTexture_; }
    // The last drawn view as RGBA, row 0 = top (golden tests of the 3D view alone).
    std::vector<std::uint8_t> readPixels() const;
    glm::ivec2 size() const { return size_; }
    // Draws that copied a kept surface layer instead of drawing the surfaces.
    int surfaceLayerReuses() const { return surfaceLayerReuses_; }
    // Labels for the axes, source and film at their projected positions (last draw).
    const std::vector<SceneLabel>& labels() const { return labels_; }

  private:
    void resize(glm::ivec2 size);
    void drawFilm(const std::vector<float>& vertices, const glm::mat4& viewProjection,
                  GLuint texture);
    // Shared by both views: the source marker and the textured film, the cone's lines (and
    // its translucent faces), drawing a line list, resolving the multisampled target.
    void drawSourceAndFilm(const glm::vec3& source, const std::array<glm::vec3, 4>& film,
                           float markerRadius, const glm::mat4& viewProjection, GLuint filmTexture);
    static void coneLines(std::vector<LineVertex>& lines, const glm::vec3& source,
                          const std::array<glm::vec3, 4>& film, const glm::vec3& filmCentre);
    static void coneFaces(std::vector<LineVertex>& lines, const glm::vec3& source,
                          const std::array<glm::vec3, 4>& film);
    void drawLines(const std::vector<LineVertex>& lines, std::size_t lineVertexCount,
                   const glm::mat4& viewProjection);
    void finish(glm::ivec2 size, bool multisample);
    // The surfaces (after the clear), or the same samples and depths copied from the last
    // draw of the same kind (single-sample or multisampled) when nothing they depend on
    // changed: turning the X-ray source and film (the azimuth, elevation, rotation sliders)
    // moves neither them nor the camera, and on llvmpipe the surfaces are most of the view's
    // cost. The multisampled layer makes the draw after a release cheap too.
    void drawSurfaces(const std::vector<SurfaceItem>& surfaces, const glm::dvec3& shift,
                      bool multisample);
    struct SurfaceLayerKey {
        glm::ivec2 size{0};
        glm::mat4 viewProjection{0.0f};
        glm::vec3 camera{0.0f};
        glm::dvec3 shift{0.0};  // the isocenter frame's
        std::vector<SurfaceItem> surfaces;
        bool operator==(const SurfaceLayerKey& o) const;
    };
    struct GpuMesh {
        GLuint vao = 0, vbo = 0, ebo = 0;
        GLsizei indexCount = 0;
        std::uint64_t generation = 0;
    };
    // The GPU copy of surface `slot`, uploaded when its generation changed.
    const GpuMesh& uploadMesh(std::size_t slot, const Mesh& mesh, std::uint64_t generation);

    ShaderProgram meshShader_, lineShader_, filmShader_;
    glm::ivec2 size_{0};
    static constexpr int kSamples = 4;
    GLuint msFbo_ = 0, msColor_ = 0, msDepth_ = 0;  // multisampled target
    GLuint resolveFbo_ = 0, resolveTexture_ = 0;    // what the UI shows
    GLuint resolveDepth_ = 0;                       // for single-sample drawing
    // The kept surface layers: [0] single-sample, [1] multisampled (the targets' formats).
    struct SurfaceLayer {
        GLuint fbo = 0, color = 0, depth = 0;
        std::optional<SurfaceLayerKey> key;  // what it holds
    } layers_[2];
    SurfaceLayerKey currentLayer_;                           // of the draw under way
    int surfaceLayerReuses_ = 0;
    std::vector<GpuMesh> meshes_;
    GLuint sphereVao_ = 0, sphereVbo_ = 0, sphereEbo_ = 0;
    GLsizei sphereIndexCount_ = 0;
    GLuint lineVao_ = 0, lineVbo_ = 0;
    GLuint filmVao_ = 0, filmVbo_ = 0;
    std::vector<SceneLabel> labels_;
};

// The orbit camera of the 3D view for a scene of radius `sceneRadiusMm` around the isocenter.
struct OrbitCamera {
    glm::mat4 view{1.0f}, projection{1.0f};
    glm::vec3 position{0.0f};
};
OrbitCamera orbitCamera(const app::View3d& view, double sceneRadiusMm, float aspect);

}  // namespace fm::render
