#include "render/SceneRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/TextureVersions.h"
#include "scene/DrrCache.h"
#include "scene/LoadedScene.h"
#include "scene/SliceImages.h"

namespace fm::render {

struct LineVertex {
    glm::vec3 position;
    glm::vec4 color;
};

namespace {

// The farthest point of the X-ray source and film from the isocentre, at any angles.
double apparatusRadius(const SceneSetup& setup) {
    const glm::dvec2 halfFilm = 0.5 * setup.filmSizeMm;
    return std::max(setup.sourceToIsocenterMm,
                    std::sqrt(setup.isocenterToFilmMm * setup.isocenterToFilmMm +
                              glm::dot(halfFilm, halfFilm)));
}

const glm::vec4 kBoxColor{0.85f, 0.85f, 0.90f, 1.0f};
const glm::vec4 kAxisColors[3] = {
    {0.95f, 0.30f, 0.30f, 1.0f}, {0.35f, 0.90f, 0.35f, 1.0f}, {0.40f, 0.55f, 1.00f, 1.0f}};
const glm::vec4 kConeColor{1.00f, 0.85f, 0.30f, 0.85f};
const glm::vec4 kConeFaceColor{1.00f, 0.85f, 0.30f, 0.07f};
const glm::vec4 kFilmFrameColor{0.60f, 0.80f, 1.00f, 1.0f};
const glm::vec3 kSourceColor{1.00f, 0.80f, 0.20f};

void line(std::vector<LineVertex>& out, glm::vec3 a, glm::vec3 b, glm::vec4 color) {
    out.push_back({a, color});
    out.push_back({b, color});
}

// Unit sphere (positions double as normals) for the source marker.
void makeSphere(std::vector<glm::vec3>& vertices, std::vector<glm::uvec3>& triangles) {
    constexpr int kRings = 12, kSegments = 24;
    for (int r = 0; r <= kRings; ++r) {
        const float theta = float(M_PI) * r / kRings;
        for (int s = 0; s <= kSegments; ++s) {
            const float phi = 2.0f * float(M_PI) * s / kSegments;
            vertices.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                  std::cos(theta));
        }
    }
    for (int r = 0; r < kRings; ++r)
        for (int s = 0; s < kSegments; ++s) {
            const unsigned a = r * (kSegments + 1) + s, b = a + kSegments + 1;
            triangles.emplace_back(a, b, a + 1);
            triangles.emplace_back(a + 1, b, b + 1);
        }
}

// Where a plane cuts the box (corner bit i: +i axis): the points on the 12 edges, in order
// around the plane (by angle in its (u, v) axes). Fewer than 3 points: no cut.
std::vector<glm::dvec3> planeCutOfBox(const SliceGeometry& slice,
                                      const std::array<glm::dvec3, 8>& box) {
    const glm::dvec3 c = slice.center(), n = slice.normal();
    std::vector<glm::dvec3> points;
    for (int a = 0; a < 8; ++a)
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (a & bit) continue;
            const double da = glm::dot(box[a] - c, n), db = glm::dot(box[a | bit] - c, n);
            if ((da > 0) == (db > 0) && da != 0.0) continue;
            const double t = da == db ? 0.0 : da / (da - db);
            points.push_back(box[a] + t * (box[a | bit] - box[a]));
        }
    if (points.size() < 3) return {};
    glm::dvec3 mid(0.0);
    for (const auto& p : points) mid += p;
    mid /= double(points.size());
    auto angle = [&](const glm::dvec3& p) {
        return std::atan2(glm::dot(p - mid, slice.v), glm::dot(p - mid, slice.u));
    };
    std::sort(points.begin(), points.end(),
              [&](const glm::dvec3& p, const glm::dvec3& q) { return angle(p) < angle(q); });
    return points;
}

const glm::vec4 kSliceFrameColor{0.45f, 0.95f, 0.65f, 1.0f};

}  // namespace

OrbitCamera orbitCamera(const app::View3d& view, double sceneRadiusMm, float aspect) {
    constexpr float kFovDeg = 30.0f;
    const float radius = float(std::max(sceneRadiusMm, 1.0));
    const float distance =
        radius / std::sin(glm::radians(kFovDeg) * 0.5f) / std::max(view.zoom, 0.05f);
    const float az = glm::radians(view.azimuthDeg), el = glm::radians(view.elevationDeg);
    // LPS world: z is superior, so z is up; azimuth 0 looks from anterior (-y).
    const glm::vec3 direction(std::sin(az) * std::cos(el), -std::cos(az) * std::cos(el),
                              std::sin(el));
    OrbitCamera camera;
    const glm::vec3 up =
        std::abs(el) > glm::radians(89.0f) ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
    // Panning moves the point looked at across the screen (right and up of the camera).
    const glm::vec3 right = glm::normalize(glm::cross(-direction, up));
    const glm::vec3 screenUp = glm::cross(right, -direction);
    const glm::vec3 target = (right * view.panX + screenUp * view.panY) * radius;
    camera.position = target + direction * distance;
    camera.view = glm::lookAt(camera.position, target, up);
    camera.projection = glm::perspective(glm::radians(kFovDeg), std::max(aspect, 0.01f),
                                         distance * 0.05f, distance + radius * 3.0f);
    return camera;
}

SceneRenderer::SceneRenderer()
    : meshShader_("mesh.vert.glsl", "mesh.frag.glsl"),
      lineShader_("line.vert.glsl", "line.frag.glsl"),
      filmShader_("film.vert.glsl", "film.frag.glsl") {
    std::vector<glm::vec3> sphere;
    std::vector<glm::uvec3> sphereTriangles;
    makeSphere(sphere, sphereTriangles);
    glGenVertexArrays(1, &sphereVao_);
    glGenBuffers(1, &sphereVbo_);
    glGenBuffers(1, &sphereEbo_);
    glBindVertexArray(sphereVao_);
    glBindBuffer(GL_ARRAY_BUFFER, sphereVbo_);
    glBufferData(GL_ARRAY_BUFFER, sphere.size() * sizeof(glm::vec3), sphere.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, sphereEbo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sphereTriangles.size() * sizeof(glm::uvec3),
                 sphereTriangles.data(), GL_STATIC_DRAW);
    sphereIndexCount_ = GLsizei(sphereTriangles.size() * 3);

    glGenVertexArrays(1, &lineVao_);
    glGenBuffers(1, &lineVbo_);
    glBindVertexArray(lineVao_);
    glBindBuffer(GL_ARRAY_BUFFER, lineVbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                          reinterpret_cast<void*>(offsetof(LineVertex, color)));

    glGenVertexArrays(1, &filmVao_);
    glGenBuffers(1, &filmVbo_);
    glBindVertexArray(filmVao_);
    glBindBuffer(GL_ARRAY_BUFFER, filmVbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float),
                          reinterpret_cast<void*>(3 * sizeof(float)));
    glBindVertexArray(0);
}

SceneRenderer::~SceneRenderer() {
    for (const GpuMesh& m : meshes_) {
        const GLuint buffers[] = {m.vbo, m.ebo};
        glDeleteBuffers(2, buffers);
        glDeleteVertexArrays(1, &m.vao);
    }
    const GLuint buffers[] = {sphereVbo_, sphereEbo_, lineVbo_, filmVbo_};
    glDeleteBuffers(4, buffers);
    const GLuint arrays[] = {sphereVao_, lineVao_, filmVao_};
    glDeleteVertexArrays(3, arrays);
    if (msFbo_) glDeleteFramebuffers(1, &msFbo_);
    if (resolveFbo_) glDeleteFramebuffers(1, &resolveFbo_);
    if (msColor_) glDeleteRenderbuffers(1, &msColor_);
    if (msDepth_) glDeleteRenderbuffers(1, &msDepth_);
    if (resolveDepth_) glDeleteRenderbuffers(1, &resolveDepth_);
    for (const SurfaceLayer& layer : layers_) {
        if (layer.fbo) glDeleteFramebuffers(1, &layer.fbo);
        if (layer.color) glDeleteRenderbuffers(1, &layer.color);
        if (layer.depth) glDeleteRenderbuffers(1, &layer.depth);
    }
    if (resolveTexture_) {
        markTextureChanged(resolveTexture_);  // its name may be reused
        glDeleteTextures(1, &resolveTexture_);
    }
}

void SceneRenderer::resize(glm::ivec2 size) {
    if (size == size_ && msFbo_) return;
    size_ = size;
    if (!msFbo_) {
        glGenFramebuffers(1, &msFbo_);
        glGenRenderbuffers(1, &msColor_);
        glGenRenderbuffers(1, &msDepth_);
        glGenFramebuffers(1, &resolveFbo_);
        glGenTextures(1, &resolveTexture_);
        glGenRenderbuffers(1, &resolveDepth_);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, msColor_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, kSamples, GL_RGBA8, size.x, size.y);
    glBindRenderbuffer(GL_RENDERBUFFER, msDepth_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, kSamples, GL_DEPTH_COMPONENT24, size.x,
                                     size.y);
    glBindFramebuffer(GL_FRAMEBUFFER, msFbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msColor_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msDepth_);

    glBindTexture(GL_TEXTURE_2D, resolveTexture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, resolveTexture_, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, resolveDepth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.x, size.y);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, resolveDepth_);

    // The kept surface layers: the same formats as their targets (copied both ways).
    for (int multisample = 0; multisample < 2; ++multisample) {
        SurfaceLayer& layer = layers_[multisample];
        if (!layer.fbo) {
            glGenFramebuffers(1, &layer.fbo);
            glGenRenderbuffers(1, &layer.color);
            glGenRenderbuffers(1, &layer.depth);
        }
        const int samples = multisample ? kSamples : 0;
        glBindRenderbuffer(GL_RENDERBUFFER, layer.color);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, size.x, size.y);
        glBindRenderbuffer(GL_RENDERBUFFER, layer.depth);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, size.x,
                                         size.y);
        glBindFramebuffer(GL_FRAMEBUFFER, layer.fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  layer.color);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  layer.depth);
        layer.key.reset();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

bool SceneRenderer::SurfaceLayerKey::operator==(const SurfaceLayerKey& o) const {
    if (size != o.size || viewProjection != o.viewProjection || camera != o.camera ||
        shift != o.shift ||
        surfaces.size() != o.surfaces.size())
        return false;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        const SurfaceItem &a = surfaces[i], &b = o.surfaces[i];
        if (a.mesh != b.mesh || a.generation != b.generation ||
            a.worldFromObject != b.worldFromObject || a.color != b.color)
            return false;
    }
    return true;
}

void SceneRenderer::drawSurfaces(const std::vector<SurfaceItem>& surfaces, const glm::dvec3& shift,
                                 bool multisample) {
    const GLuint target = multisample ? msFbo_ : resolveFbo_;
    SurfaceLayer& layer = layers_[multisample ? 1 : 0];
    auto copy = [&](GLuint from, GLuint to) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
        glBlitFramebuffer(0, 0, size_.x, size_.y, 0, 0, size_.x, size_.y,
                          GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, target);
    };
    if (layer.key && *layer.key == currentLayer_) {
        copy(layer.fbo, target);
        ++surfaceLayerReuses_;
        return;
    }
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        const SurfaceItem& item = surfaces[i];
        if (!item.mesh) continue;
        const GpuMesh& gpu = uploadMesh(i, *item.mesh, item.generation);
        // Isocenter frame of the CT world: shifted; each bone first moved by its pose.
        const glm::dmat4 model = glm::translate(glm::dmat4(1.0), shift) * item.worldFromObject;
        meshShader_.set("uModel", glm::mat4(model));
        meshShader_.set("uColor", item.color);
        meshShader_.set("uAmbient", 0.25f);
        glBindVertexArray(gpu.vao);
        glDrawElements(GL_TRIANGLES, gpu.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    copy(target, layer.fbo);
    layer.key = currentLayer_;
}

const SceneRenderer::GpuMesh& SceneRenderer::uploadMesh(std::size_t slot, const Mesh& mesh,
                                                        std::uint64_t generation) {
    while (meshes_.size() <= slot) {
        GpuMesh m;
        glGenVertexArrays(1, &m.vao);
        glGenBuffers(1, &m.vbo);
        glGenBuffers(1, &m.ebo);
        meshes_.push_back(m);
    }
    GpuMesh& gpu = meshes_[slot];
    if (generation == gpu.generation) return gpu;
    gpu.generation = generation;
    std::vector<glm::vec3> interleaved;
    interleaved.reserve(mesh.positions.size() * 2);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        interleaved.push_back(mesh.positions[i]);
        interleaved.push_back(i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 0, 1));
    }
    glBindVertexArray(gpu.vao);
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vbo);
    glBufferData(GL_ARRAY_BUFFER, interleaved.size() * sizeof(glm::vec3), interleaved.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3),
                          reinterpret_cast<void*>(sizeof(glm::vec3)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, mesh.triangles.size() * sizeof(glm::uvec3),
                 mesh.triangles.data(), GL_STATIC_DRAW);
    gpu.indexCount = GLsizei(mesh.triangles.size() * 3);
    glBindVertexArray(0);
    return gpu;
}

// Textured triangles (x, y, z, s, t per vertex) with the film shader: the film quad and the
// slice plane's cut through the box are drawn the same way.
void SceneRenderer::drawFilm(const std::vector<float>& vertices, const glm::mat4& viewProjection,
                             GLuint texture) {
    filmShader_.use();
    filmShader_.set("uViewProjection", viewProjection);
    filmShader_.set("uImage", 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    glBindVertexArray(filmVao_);
    glBindBuffer(GL_ARRAY_BUFFER, filmVbo_);
    glBufferData(GL_ARRAY_BUFFER, vertices.size() * sizeof(float), vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size() / 5));
}

void SceneRenderer::draw(const app::LoadedScene* scene, const std::vector<SurfaceItem>& surfaces,
                         const Pose& pose, const app::View3d& view, GLuint filmTexture,
                         glm::ivec2 size, bool multisample, bool slicePlane) {
    size = glm::max(size, glm::ivec2(16));
    resize(size);
    labels_.clear();

    glBindFramebuffer(GL_FRAMEBUFFER, multisample ? msFbo_ : resolveFbo_);
    glViewport(0, 0, size.x, size.y);
    glClearColor(0.11f, 0.12f, 0.14f, 1.0f);
    if (!scene || slicePlane) glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);  // else below

    if (scene) {
        // Isocenter frame: volume-world point p -> p - centre + offset.
        const glm::dvec3 shift = pose.offset - scene->center;
        auto toScene = [&](const glm::dvec3& p) { return glm::vec3(p + shift); };
        const ProjectionGeometry g = app::appGeometry(*scene, pose);
        const DetectorGeometry& d = g.detector;
        const glm::dvec3 corners[4] = {
            d.pixelCenter(-0.5, -0.5), d.pixelCenter(d.size.x - 0.5, -0.5),
            d.pixelCenter(d.size.x - 0.5, d.size.y - 0.5), d.pixelCenter(-0.5, d.size.y - 0.5)};
        const glm::vec3 source = toScene(g.source);
        // The slice mode shows the volume alone: frame its box, not the X-ray apparatus. The
        // apparatus turns about the isocentre, so its reach is computed from the set-up, not
        // from the turned points: their lengths differ in the last bits from angle to angle,
        // which moved the camera by rounding and made every turn redraw the surfaces.
        double radius = slicePlane ? 0.0 : apparatusRadius(scene->setup);
        for (const auto& c : scene->boxCorners)
            radius = std::max(radius, double(glm::length(toScene(c))));

        const OrbitCamera camera = orbitCamera(view, radius, float(size.x) / float(size.y));
        const glm::mat4 viewProjection = camera.projection * camera.view;
        auto label = [&](glm::vec3 p, const std::string& text, glm::vec4 color) {
            const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
            if (clip.w <= 0.0f) return;
            const glm::vec2 ndc = glm::vec2(clip) / clip.w;
            labels_.push_back(
                {{(ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y}, text, color});
        };

        glEnable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);

        meshShader_.use();
        meshShader_.set("uViewProjection", viewProjection);
        meshShader_.set("uCameraPosition", camera.position);
        meshShader_.set("uAlpha", 1.0f);
        std::vector<glm::dvec3> cut;
        if (slicePlane) {
            // The slice's cut through the box, textured with the user's slice: a texture
            // coordinate is the point's continuous pixel position (t = 0: image row 0).
            const SliceGeometry sl = app::appSlice(*scene, pose);
            cut = planeCutOfBox(sl, scene->boxCorners);
            std::vector<float> fan;
            auto vertex = [&](const glm::dvec3& p) {
                const glm::dvec3 rel = p - sl.origin;
                const glm::vec3 q = toScene(p);
                fan.insert(fan.end(),
                           {q.x, q.y, q.z,
                            float((glm::dot(rel, sl.u) / sl.spacing.x + 0.5) / sl.size.x),
                            float((glm::dot(rel, sl.v) / sl.spacing.y + 0.5) / sl.size.y)});
            };
            for (std::size_t i = 1; i + 1 < cut.size(); ++i) {
                vertex(cut[0]);
                vertex(cut[i]);
                vertex(cut[i + 1]);
            }
            if (!fan.empty()) drawFilm(fan, viewProjection, filmTexture);
            meshShader_.use();
        }
        if (slicePlane) {  // translucent, so the plane inside shows through it
            meshShader_.set("uAlpha", 0.3f);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(GL_FALSE);
        }
        if (slicePlane) {
            for (std::size_t i = 0; view.showBone && i < surfaces.size(); ++i) {
                const SurfaceItem& item = surfaces[i];
                if (!item.mesh) continue;
                const GpuMesh& gpu = uploadMesh(i, *item.mesh, item.generation);
                const glm::dmat4 model =
                    glm::translate(glm::dmat4(1.0), shift) * item.worldFromObject;
                meshShader_.set("uModel", glm::mat4(model));
                meshShader_.set("uColor", item.color);
                meshShader_.set("uAmbient", 0.25f);
                glBindVertexArray(gpu.vao);
                glDrawElements(GL_TRIANGLES, gpu.indexCount, GL_UNSIGNED_INT, nullptr);
            }
        } else {
            currentLayer_ = {size, viewProjection, camera.position, shift,
                             view.showBone ? surfaces : std::vector<SurfaceItem>{}};
            drawSurfaces(currentLayer_.surfaces, shift, multisample);
        }
        if (slicePlane) {
            meshShader_.set("uAlpha", 1.0f);
            glDepthMask(GL_TRUE);
            glDisable(GL_BLEND);
        }
        const bool apparatus = view.showApparatus && !slicePlane;
        if (apparatus)
            drawSourceAndFilm(source, {toScene(corners[0]), toScene(corners[1]), toScene(corners[2]),
                                       toScene(corners[3])},
                              float(radius) * 0.02f, viewProjection, filmTexture);

        std::vector<LineVertex> lines;
        if (view.showBox) {
            for (int a = 0; a < 8; ++a)
                for (int bit = 1; bit < 8; bit <<= 1)
                    if (!(a & bit))
                        line(lines, toScene(scene->boxCorners[a]),
                             toScene(scene->boxCorners[a | bit]), kBoxColor);
            // x/y/z axes from the first voxel corner, longer than the box (as in 2011).
            const glm::vec3 o = toScene(scene->boxCorners[0]);
            for (int axis = 0; axis < 3; ++axis) {
                const glm::vec3 tip = o + (toScene(scene->boxCorners[1 << axis]) - o) * 1.35f;
                line(lines, o, tip, kAxisColors[axis]);
                label(tip, std::string(1, "xyz"[axis]), kAxisColors[axis]);
            }
        }
        if (slicePlane && view.showApparatus && !cut.empty()) {
            for (std::size_t i = 0; i < cut.size(); ++i)
                line(lines, toScene(cut[i]), toScene(cut[(i + 1) % cut.size()]), kSliceFrameColor);
            label(toScene(cut[0]), "slice", kSliceFrameColor);
        }
        const std::array<glm::vec3, 4> film{toScene(corners[0]), toScene(corners[1]),
                                            toScene(corners[2]), toScene(corners[3])};
        if (apparatus) {
            coneLines(lines, source, film, toScene(d.center()));
            label(source, "source", glm::vec4(kSourceColor, 1.0f));
            label(film[2], "film", kFilmFrameColor);
        }
        const std::size_t lineVertexCount = lines.size();
        if (apparatus) coneFaces(lines, source, film);  // translucent, drawn last
        drawLines(lines, lineVertexCount, viewProjection);
    }
    finish(size, multisample);
}

void SceneRenderer::drawSourceAndFilm(const glm::vec3& source, const std::array<glm::vec3, 4>& film,
                                      float markerRadius, const glm::mat4& viewProjection,
                                      GLuint filmTexture) {
    meshShader_.use();
    meshShader_.set("uModel",
                    glm::scale(glm::translate(glm::mat4(1.0f), source), glm::vec3(markerRadius)));
    meshShader_.set("uColor", kSourceColor);
    meshShader_.set("uAmbient", 0.5f);
    glBindVertexArray(sphereVao_);
    glDrawElements(GL_TRIANGLES, sphereIndexCount_, GL_UNSIGNED_INT, nullptr);
    // Film: a quad textured with its image; texture t = 0 is image row 0.
    const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<float> quad;
    for (int i : {0, 1, 2, 0, 2, 3})
        quad.insert(quad.end(), {film[i].x, film[i].y, film[i].z, uv[i][0], uv[i][1]});
    drawFilm(quad, viewProjection, filmTexture);
}

void SceneRenderer::coneLines(std::vector<LineVertex>& lines, const glm::vec3& source,
                              const std::array<glm::vec3, 4>& film, const glm::vec3& filmCentre) {
    for (int i = 0; i < 4; ++i) {
        line(lines, source, film[i], kConeColor);
        line(lines, film[i], film[(i + 1) % 4], kFilmFrameColor);
    }
    line(lines, source, filmCentre, glm::vec4(glm::vec3(kConeColor), 0.35f));
}

void SceneRenderer::coneFaces(std::vector<LineVertex>& lines, const glm::vec3& source,
                              const std::array<glm::vec3, 4>& film) {
    for (int i = 0; i < 4; ++i) {
        lines.push_back({source, kConeFaceColor});
        lines.push_back({film[i], kConeFaceColor});
        lines.push_back({film[(i + 1) % 4], kConeFaceColor});
    }
}

// Lines (the first `lineVertexCount` vertices), then translucent triangles without depth
// writes.
void SceneRenderer::drawLines(const std::vector<LineVertex>& lines, std::size_t lineVertexCount,
                              const glm::mat4& viewProjection) {
    lineShader_.use();
    lineShader_.set("uViewProjection", viewProjection);
    glBindVertexArray(lineVao_);
    glBindBuffer(GL_ARRAY_BUFFER, lineVbo_);
    glBufferData(GL_ARRAY_BUFFER, lines.size() * sizeof(LineVertex), lines.data(), GL_STREAM_DRAW);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDrawArrays(GL_LINES, 0, GLsizei(lineVertexCount));
    glDepthMask(GL_FALSE);
    glDrawArrays(GL_TRIANGLES, GLsizei(lineVertexCount), GLsizei(lines.size() - lineVertexCount));
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(0);
}

void SceneRenderer::finish(glm::ivec2 size, bool multisample) {
    if (multisample) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, msFbo_);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbo_);
        glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    markTextureChanged(resolveTexture_);
}

void SceneRenderer::drawRig(const std::vector<RigCamera>& cameras,
                            const std::vector<SurfaceItem>& surfaces, const glm::dvec3& centre,
                            const app::View3d& view, glm::ivec2 size, bool multisample) {
    size = glm::max(size, glm::ivec2(16));
    resize(size);
    labels_.clear();
    glBindFramebuffer(GL_FRAMEBUFFER, multisample ? msFbo_ : resolveFbo_);
    glViewport(0, 0, size.x, size.y);
    glClearColor(0.11f, 0.12f, 0.14f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // The rig's frame: the world moved so `centre` is the origin; framed to hold every source
    // and film.
    auto toScene = [&](const glm::dvec3& p) { return glm::vec3(p - centre); };
    double radius = 1.0;
    for (const RigCamera& c : cameras) {
        radius = std::max(radius, double(glm::length(toScene(c.source))));
        for (const auto& f : c.film) radius = std::max(radius, double(glm::length(toScene(f))));
    }
    const OrbitCamera camera = orbitCamera(view, radius, float(size.x) / float(size.y));
    const glm::mat4 viewProjection = camera.projection * camera.view;
    auto label = [&](glm::vec3 p, const std::string& text, glm::vec4 color) {
        const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
        if (clip.w <= 0.0f) return;
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        labels_.push_back({{(ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y}, text, color});
    };
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    meshShader_.use();
    meshShader_.set("uViewProjection", viewProjection);
    meshShader_.set("uCameraPosition", camera.position);
    meshShader_.set("uAlpha", 1.0f);
    const glm::dmat4 shift = glm::translate(glm::dmat4(1.0), -centre);
    for (std::size_t i = 0; view.showBone && i < surfaces.size(); ++i) {
        const SurfaceItem& item = surfaces[i];
        if (!item.mesh) continue;
        const GpuMesh& gpu = uploadMesh(i, *item.mesh, item.generation);
        meshShader_.set("uModel", glm::mat4(shift * item.worldFromObject));
        meshShader_.set("uColor", item.color);
        meshShader_.set("uAmbient", 0.25f);
        glBindVertexArray(gpu.vao);
        glDrawElements(GL_TRIANGLES, gpu.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    std::vector<LineVertex> lines;
    std::vector<std::array<glm::vec3, 4>> films;
    for (const RigCamera& c : cameras) {
        films.push_back({toScene(c.film[0]), toScene(c.film[1]), toScene(c.film[2]), toScene(c.film[3])});
        if (!view.showApparatus) continue;
        drawSourceAndFilm(toScene(c.source), films.back(), float(radius) * 0.02f, viewProjection, c.texture);
        coneLines(lines, toScene(c.source), films.back(),
                  0.25f * (films.back()[0] + films.back()[1] + films.back()[2] + films.back()[3]));
        label(toScene(c.source), c.name, glm::vec4(kSourceColor, 1.0f));
    }
    const std::size_t lineVertexCount = lines.size();
    for (std::size_t i = 0; view.showApparatus && i < cameras.size(); ++i)
        coneFaces(lines, toScene(cameras[i].source), films[i]);
    if (!lines.empty()) drawLines(lines, lineVertexCount, viewProjection);
    glDisable(GL_DEPTH_TEST);
    finish(size, multisample);
}

std::vector<std::uint8_t> SceneRenderer::readPixels() const {
    std::vector<std::uint8_t> bottomUp(std::size_t(size_.x) * size_.y * 4), out(bottomUp.size());
    glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const std::size_t row = std::size_t(size_.x) * 4;
    for (int y = 0; y < size_.y; ++y)
        std::copy_n(&bottomUp[(size_.y - 1 - y) * row], row, &out[y * row]);
    return out;
}

}  // namespace fm::render
