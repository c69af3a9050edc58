#include "ui/FrameDamage.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace fm::app {

PixelRect intersect(const PixelRect& a, const PixelRect& b) {
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1),
            std::min(a.y1, b.y1)};
}

PixelRect unite(const PixelRect& a, const PixelRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1),
            std::max(a.y1, b.y1)};
}

bool sameTriangle(const DrawnTriangle& a, const DrawnTriangle& b) {
    return std::memcmp(a.vertices, b.vertices, sizeof(a.vertices)) == 0 &&
           a.scissor == b.scissor && a.texture == b.texture &&
           a.textureVersion == b.textureVersion;
}

PixelRect commandScissor(const ImVec4& clip, glm::ivec2 framebuffer) {
    // As imgui_impl_opengl3.cpp (1.86): skipped when empty, else
    // glScissor((int)min.x, (int)(fb_height - max.y), (int)(max.x - min.x), (int)(max.y - min.y)).
    if (clip.z <= clip.x || clip.w <= clip.y) return {};
    const int x = int(clip.x), width = int(clip.z - clip.x);
    const int glY = int(float(framebuffer.y) - clip.w), height = int(clip.w - clip.y);
    const PixelRect scissor{x, framebuffer.y - (glY + height), x + width, framebuffer.y - glY};
    return intersect(scissor, {0, 0, framebuffer.x, framebuffer.y});
}

namespace {

// The pixels whose centres a triangle can cover, one pixel wider on each side (the
// rasteriser's snapping of vertices to its sub-pixel grid).
PixelRect boundingPixels(const ImDrawVert (&v)[3]) {
    float minX = v[0].pos.x, maxX = minX, minY = v[0].pos.y, maxY = minY;
    for (const ImDrawVert& p : v) {
        minX = std::min(minX, p.pos.x);
        maxX = std::max(maxX, p.pos.x);
        minY = std::min(minY, p.pos.y);
        maxY = std::max(maxY, p.pos.y);
    }
    // Clamped first: a float far outside the framebuffer does not fit in an int.
    const auto toInt = [](float f) { return int(std::clamp(f, -1e8f, 1e8f)); };
    return {toInt(std::floor(minX)) - 1, toInt(std::floor(minY)) - 1, toInt(std::ceil(maxX)) + 1,
            toInt(std::ceil(maxY)) + 1};
}

PixelRect reachOf(const std::vector<DrawnTriangle>& triangles, std::size_t from, std::size_t to) {
    PixelRect r;
    for (std::size_t i = from; i < to; ++i) r = unite(r, triangles[i].reach);
    return r;
}

// Triangles equal at the start and at the end of both lists are drawn alike; the middle of
// either list is what can differ.
PixelRect changedReach(const std::vector<DrawnTriangle>& before,
                       const std::vector<DrawnTriangle>& now) {
    const std::size_t shorter = std::min(before.size(), now.size());
    std::size_t prefix = 0;
    while (prefix < shorter && sameTriangle(before[prefix], now[prefix])) ++prefix;
    std::size_t suffix = 0;
    while (suffix < shorter - prefix &&
           sameTriangle(before[before.size() - 1 - suffix], now[now.size() - 1 - suffix]))
        ++suffix;
    return unite(reachOf(before, prefix, before.size() - suffix),
                 reachOf(now, prefix, now.size() - suffix));
}

bool overlap(const PixelRect& a, const PixelRect& b) { return !intersect(a, b).empty(); }

}  // namespace

FrameDrawing recordDrawing(const ImDrawData& data, glm::ivec2 framebuffer,
                           const TextureVersionOf& versionOf) {
    FrameDrawing frame;
    frame.size = framebuffer;
    frame.comparable = data.DisplayPos.x == 0.0f && data.DisplayPos.y == 0.0f &&
                       data.FramebufferScale.x == 1.0f && data.FramebufferScale.y == 1.0f;
    for (int l = 0; l < data.CmdListsCount; ++l) {
        const ImDrawList& list = *data.CmdLists[l];
        std::vector<DrawnTriangle>& triangles = frame.lists.emplace_back();
        triangles.reserve(std::size_t(list.IdxBuffer.Size / 3));
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            if (cmd.UserCallback) {
                frame.comparable = false;
                continue;
            }
            const PixelRect scissor = commandScissor(cmd.ClipRect, framebuffer);
            const std::uint64_t version = versionOf(cmd.TextureId);
            for (unsigned i = 0; i + 2 < cmd.ElemCount; i += 3) {
                DrawnTriangle t;
                for (int k = 0; k < 3; ++k)
                    t.vertices[k] = list.VtxBuffer[int(cmd.VtxOffset +
                                                       list.IdxBuffer[int(cmd.IdxOffset + i + k)])];
                t.scissor = scissor;
                t.texture = cmd.TextureId;
                t.textureVersion = version;
                t.reach = intersect(boundingPixels(t.vertices), scissor);
                triangles.push_back(t);
            }
        }
    }
    return frame;
}

std::vector<PixelRect> damagedRects(const FrameDrawing& before, const FrameDrawing& now) {
    const PixelRect whole{0, 0, now.size.x, now.size.y};
    if (!before.comparable || !now.comparable || before.size != now.size) return {whole};
    std::vector<PixelRect> rects;
    const std::size_t lists = std::max(before.lists.size(), now.lists.size());
    static const std::vector<DrawnTriangle> none;
    for (std::size_t l = 0; l < lists; ++l) {
        const PixelRect r = changedReach(l < before.lists.size() ? before.lists[l] : none,
                                         l < now.lists.size() ? now.lists[l] : none);
        if (!r.empty()) rects.push_back(intersect(r, whole));
    }
    return disjointRects(std::move(rects));
}

std::vector<PixelRect> disjointRects(std::vector<PixelRect> rects) {
    std::erase_if(rects, [](const PixelRect& r) { return r.empty(); });
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t i = 0; i < rects.size() && !merged; ++i)
            for (std::size_t j = i + 1; j < rects.size() && !merged; ++j)
                if (overlap(rects[i], rects[j])) {
                    rects[i] = unite(rects[i], rects[j]);
                    rects.erase(rects.begin() + std::ptrdiff_t(j));
                    merged = true;
                }
    }
    return rects;
}

void clipDrawData(ImDrawData& data, glm::ivec2 framebuffer, const std::vector<PixelRect>& rects) {
    for (int l = 0; l < data.CmdListsCount; ++l) {
        ImDrawList& list = *data.CmdLists[l];
        ImVector<ImDrawCmd> clipped;
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            const PixelRect scissor = commandScissor(cmd.ClipRect, framebuffer);
            for (const PixelRect& r : rects) {
                const PixelRect part = intersect(scissor, r);
                if (part.empty()) continue;
                ImDrawCmd copy = cmd;
                copy.ClipRect = ImVec4(float(part.x0), float(part.y0), float(part.x1),
                                       float(part.y1));
                clipped.push_back(copy);
            }
        }
        list.CmdBuffer.swap(clipped);
    }
}

}  // namespace fm::app
