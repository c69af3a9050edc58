#include "mesh/MarchingCubes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include "core/Error.h"
#include "core/Parallel.h"
#include "mesh/MarchingCubesTable.h"
#include "mesh/MeshComponents.h"

namespace fm {
namespace {

// Edge vertices stay this fraction of a voxel away from the corners: a value equal to the
// isovalue would otherwise put a vertex on a corner, where vertices of several edges coincide
// and triangles collapse to zero area. 1e-3 voxel is far above float resolution at CT world
// coordinates (~6e-5 mm at 800 mm) and far below any meaningful geometric error.
constexpr float kEdgeMargin = 1e-3f;

// Set bits of a 3-bit owned-edge mask (a table: no popcnt instruction is assumed).
constexpr std::uint32_t kBitCount3[8] = {0, 1, 1, 2, 1, 2, 2, 3};

// The working grid: the ROI plus one virtual padding layer on every side. Local point
// u in [0, m + 1] per axis is voxel lo + u - 1; u = 0 and u = m + 1 are padding (below iso).
// Point rows are (uy, uz); cube (u) spans points u .. u + 1 and owns the three edges that
// leave point u in +x, +y, +z (so each edge is intersected once, by its owner).
struct Grid {
    glm::ivec3 lo{0}, m{0}, p{0};  // ROI start (voxels), ROI size, padded size (m + 2)
    std::size_t sliceStride = 0;   // p.x * p.y
    const Volume* volume = nullptr;
    float pad = 0.0f;
    float iso = 0.0f;

    std::size_t pointIndex(int ux, int uy, int uz) const {
        return static_cast<std::size_t>(ux) + static_cast<std::size_t>(p.x) * uy +
               sliceStride * static_cast<std::size_t>(uz);
    }
    int rowIndex(int uy, int uz) const { return uy + p.y * uz; }
    // Value at a local point; anything outside the ROI is padding.
    float value(int ux, int uy, int uz) const {
        if (ux < 1 || uy < 1 || uz < 1 || ux > m.x || uy > m.y || uz > m.z) return pad;
        return volume->at(lo.x + ux - 1, lo.y + uy - 1, lo.z + uz - 1);
    }
};

struct RowInfo {
    int insideFirst = std::numeric_limits<int>::max();  // first/last inside point of the row
    int insideLast = -1;
    int cubeFirst = 0, cubeLast = -1;  // cube range worth visiting (empty when last < first)
    std::uint32_t edgeVertices = 0;    // crossed edges owned by this point row
    std::uint32_t triangles = 0;
    std::size_t vertexBase = 0, triangleBase = 0;
};

struct Placement {
    glm::dmat3 toWorld;     // direction * diag(spacing)
    glm::mat3 gradToWorld;  // direction * diag(1 / spacing)
    glm::dvec3 origin;
};

struct EdgeVertex {
    glm::vec3 position;
    glm::vec3 normal;
};

// Vertex on the edge leaving local point (ux, uy, uz) along `axis`. Normals are the
// interpolated central-difference gradient, negated (pointing to lower values: outward).
EdgeVertex makeEdgeVertex(const Grid& g, const Placement& place, int ux, int uy, int uz, int axis) {
    const glm::ivec3 a(ux, uy, uz);
    glm::ivec3 b = a;
    b[axis] += 1;
    float v0, v1;
    glm::vec3 g0, g1;
    // Both central differences stay inside the ROI: read the volume directly.
    if (glm::all(glm::greaterThanEqual(a, glm::ivec3(2))) &&
        glm::all(glm::lessThanEqual(b, g.m - 1))) {
        const Volume& vol = *g.volume;
        const std::ptrdiff_t sx = 1, sy = vol.dims.x,
                             sz = static_cast<std::ptrdiff_t>(vol.dims.x) * vol.dims.y;
        const std::ptrdiff_t step = axis == 0 ? sx : axis == 1 ? sy : sz;
        const float* p0 = &vol.values[vol.index(g.lo.x + ux - 1, g.lo.y + uy - 1, g.lo.z + uz - 1)];
        const float* p1 = p0 + step;
        v0 = p0[0];
        v1 = p1[0];
        g0 = glm::vec3(p0[sx] - p0[-sx], p0[sy] - p0[-sy], p0[sz] - p0[-sz]);
        g1 = glm::vec3(p1[sx] - p1[-sx], p1[sy] - p1[-sy], p1[sz] - p1[-sz]);
    } else {
        v0 = g.value(a.x, a.y, a.z);
        v1 = g.value(b.x, b.y, b.z);
        g0 = glm::vec3(g.value(a.x + 1, a.y, a.z) - g.value(a.x - 1, a.y, a.z),
                       g.value(a.x, a.y + 1, a.z) - g.value(a.x, a.y - 1, a.z),
                       g.value(a.x, a.y, a.z + 1) - g.value(a.x, a.y, a.z - 1));
        g1 = glm::vec3(g.value(b.x + 1, b.y, b.z) - g.value(b.x - 1, b.y, b.z),
                       g.value(b.x, b.y + 1, b.z) - g.value(b.x, b.y - 1, b.z),
                       g.value(b.x, b.y, b.z + 1) - g.value(b.x, b.y, b.z - 1));
    }
    float t = (g.iso - v0) / (v1 - v0);  // v0 and v1 lie on different sides, so v1 != v0
    // Written so that NaN (a NaN or infinite voxel value) lands on the margin, not in the mesh.
    t = t > kEdgeMargin ? (t < 1.0f - kEdgeMargin ? t : 1.0f - kEdgeMargin) : kEdgeMargin;
    glm::dvec3 voxel = glm::dvec3(a + g.lo - 1);
    voxel[axis] += t;
    EdgeVertex out;
    out.position = glm::vec3(place.origin + place.toWorld * voxel);
    // Twice the gradient (central differences without the 1/2): only the direction matters.
    glm::vec3 n = -(place.gradToWorld * (g0 + t * (g1 - g0)));
    float len2 = glm::dot(n, n);
    if (!(len2 > 1e-30f) || !std::isfinite(len2)) {
        // Flat gradient (plateaus): point from the inside corner to the outside one.
        glm::vec3 axisDir(0.0f);
        axisDir[axis] = v0 >= g.iso ? 1.0f : -1.0f;
        n = place.gradToWorld * axisDir;
        len2 = glm::dot(n, n);
    }
    out.normal = n / std::sqrt(len2);
    return out;
}

// Crossed owned edges of a point as bits x, y, z.
inline unsigned ownedBits(const std::uint8_t* cls, std::size_t pi, std::size_t rowStride,
                          std::size_t sliceStride) {
    const unsigned b = cls[pi];
    return (b ^ cls[pi + 1]) | ((b ^ cls[pi + rowStride]) << 1) |
           ((b ^ cls[pi + sliceStride]) << 2);
}

inline unsigned cubeCase(const std::uint8_t* cls, std::size_t pi, std::size_t rowStride,
                         std::size_t sliceStride) {
    const std::uint8_t* c0 = cls + pi;
    const std::uint8_t* c1 = c0 + rowStride;
    const std::uint8_t* c2 = c0 + sliceStride;
    const std::uint8_t* c3 = c2 + rowStride;
    return c0[0] | (c0[1] << 1) | (c1[0] << 2) | (c1[1] << 3) | (c2[0] << 4) | (c2[1] << 5) |
           (c3[0] << 6) | (c3[1] << 7);
}

void checkOptions(const Volume& volume, const MarchingCubesOptions& o, glm::ivec3& lo,
                  glm::ivec3& hi) {
    volume.validate("marching cubes: volume '" + volume.meta.source + "'");
    if (volume.values.size() != volume.voxelCount())
        throw Error("marching cubes: volume '" + volume.meta.source + "' holds no values");
    if (!std::isfinite(o.isoValue)) throw Error("marching cubes: isovalue must be finite");
    if (o.padValue && !(*o.padValue < o.isoValue))
        throw Error("marching cubes: pad value must be below the isovalue");
    if (o.keepLargestComponents < 0)
        throw Error("marching cubes: number of components to keep must not be negative");
    if (o.onlyComponentRank && *o.onlyComponentRank < 0)
        throw Error("marching cubes: component rank must not be negative");
    if (o.threads < 0) throw Error("marching cubes: thread count must not be negative");
    lo = o.roiMin.value_or(glm::ivec3(0));
    hi = o.roiMax.value_or(volume.dims - 1);
    for (int a = 0; a < 3; ++a) {
        if (lo[a] < 0 || hi[a] >= volume.dims[a] || lo[a] > hi[a]) {
            std::ostringstream msg;
            msg << "marching cubes: region of interest (" << lo.x << "," << lo.y << "," << lo.z
                << ")-(" << hi.x << "," << hi.y << "," << hi.z
                << ") is empty or outside the volume of " << volume.dims.x << " x " << volume.dims.y
                << " x " << volume.dims.z << " voxels";
            throw Error(msg.str());
        }
    }
}

}  // namespace

Mesh marchingCubes(const Volume& volume, const MarchingCubesOptions& options) {
    glm::ivec3 lo, hi;
    checkOptions(volume, options, lo, hi);
    const auto& cases = mc::cubeCases();
    const int threads = options.threads <= 0 ? defaultThreadCount() : options.threads;

    Grid g;
    g.volume = &volume;
    g.lo = lo;
    g.m = hi - lo + 1;
    g.p = g.m + 2;
    g.sliceStride = static_cast<std::size_t>(g.p.x) * g.p.y;
    g.iso = static_cast<float>(options.isoValue);
    const std::size_t rowStride = g.p.x;
    const std::size_t sliceStride = g.sliceStride;

    // Pass 1: classify every ROI voxel (inside = value >= iso), note where each row has inside
    // points, and the ROI minimum for the padding value. Padding stays 0 (outside). The arrays
    // get kWordSlack spare bytes so that 8-byte reads at the last row stay in bounds.
    // Both byte arrays are left uninitialised and written in full by the parallel passes: a
    // zeroing memset up front would touch every page twice (it cost ~20% on large CTs).
    constexpr std::size_t kWordSlack = 8;
    const std::size_t byteCount = sliceStride * g.p.z + kWordSlack;
    const std::unique_ptr<std::uint8_t[]> clsStore(new std::uint8_t[byteCount]);
    // Per point: its crossed owned edges (bits x, y, z), written by pass 2.
    const std::unique_ptr<std::uint8_t[]> ownedStore(new std::uint8_t[byteCount]);
    std::uint8_t* const cls = clsStore.get();
    std::uint8_t* const owned = ownedStore.get();
    // Padding slices, the slice past the last cube layer, and the slack: all outside / none.
    std::memset(cls, 0, sliceStride);
    std::memset(cls + sliceStride * (g.p.z - 1), 0, sliceStride + kWordSlack);
    std::memset(owned + sliceStride * (g.p.z - 1), 0, sliceStride + kWordSlack);
    std::vector<RowInfo> rows(static_cast<std::size_t>(g.p.y) * g.p.z);
    std::vector<float> layerMin(g.p.z, std::numeric_limits<float>::infinity());
    const float iso = g.iso;
    parallelFor(
        g.m.z, threads,
        [&](int begin, int end) {
            for (int uz = begin + 1; uz <= end; ++uz) {
                float lowest = std::numeric_limits<float>::infinity();
                // Padding rows and row ends of this slice.
                std::memset(&cls[g.pointIndex(0, 0, uz)], 0, rowStride);
                std::memset(&cls[g.pointIndex(0, g.p.y - 1, uz)], 0, rowStride);
                for (int uy = 1; uy <= g.m.y; ++uy) {
                    cls[g.pointIndex(0, uy, uz)] = 0;
                    cls[g.pointIndex(g.p.x - 1, uy, uz)] = 0;
                }
                for (int uy = 1; uy <= g.m.y; ++uy) {
                    const float* src =
                        &volume.values[volume.index(lo.x, lo.y + uy - 1, lo.z + uz - 1)];
                    std::uint8_t* dst = &cls[g.pointIndex(1, uy, uz)];
                    // Locals: byte stores may alias anything, which would otherwise force
                    // reloading iso and the row length every voxel (and block vectorising).
                    const float isoHere = iso;
                    const int width = g.m.x;
                    for (int x = 0; x < width; ++x) dst[x] = src[x] >= isoHere;
                    // Minimum in 8 independent lanes: a single running minimum is a serial
                    // dependency the compiler may not vectorise (NaN semantics).
                    float lane[8];
                    std::fill(lane, lane + 8, std::numeric_limits<float>::infinity());
                    int x = 0;
                    for (; x + 8 <= width; x += 8)
                        for (int k = 0; k < 8; ++k) lane[k] = std::min(lane[k], src[x + k]);
                    for (; x < width; ++x) lane[0] = std::min(lane[0], src[x]);
                    const float rowLowest = *std::min_element(lane, lane + 8);
                    lowest = std::min(lowest, rowLowest);
                    const void* firstInside = std::memchr(dst, 1, width);
                    if (!firstInside) continue;
                    int last = width - 1;
                    while (!dst[last]) --last;
                    RowInfo& row = rows[g.rowIndex(uy, uz)];
                    row.insideFirst =
                        static_cast<int>(static_cast<const std::uint8_t*>(firstInside) - dst) + 1;
                    row.insideLast = last + 1;
                }
                layerMin[uz] = lowest;
            }
        },
        4);
    if (options.padValue) {
        g.pad = static_cast<float>(*options.padValue);
    } else {
        const float lowest = *std::min_element(layerMin.begin(), layerMin.end());
        g.pad = lowest < iso ? lowest : iso - 1.0f;
    }

    // 8 bytes of a byte array as one word, to skip 7 empty cubes at once.
    constexpr std::uint64_t kAllInside = 0x0101010101010101ull;
    const auto word = [](const std::uint8_t* p) {
        std::uint64_t w;
        std::memcpy(&w, p, sizeof w);
        return w;
    };

    // Pass 2: per cube row, the cubes worth visiting (those near an inside point of the four
    // point rows it touches: the rest are all outside and are skipped), the crossed edges its
    // point row owns, and its triangle count.
    const int cubeRowsY = g.m.y + 1, cubeRowsZ = g.m.z + 1;
    parallelFor(
        cubeRowsZ, threads,
        [&](int begin, int end) {
            for (int uz = begin; uz < end; ++uz) {
                for (int uy = 0; uy < cubeRowsY; ++uy) {
                    RowInfo& row = rows[g.rowIndex(uy, uz)];
                    int first = std::numeric_limits<int>::max(), last = -1;
                    for (int dz = 0; dz < 2; ++dz)
                        for (int dy = 0; dy < 2; ++dy) {
                            const RowInfo& q = rows[g.rowIndex(uy + dy, uz + dz)];
                            first = std::min(first, q.insideFirst);
                            last = std::max(last, q.insideLast);
                        }
                    const std::size_t base = g.pointIndex(0, uy, uz);
                    // Owned edges default to none; the loop below fills the visited points.
                    std::memset(owned + base, 0, rowStride);
                    if (uy + 1 == cubeRowsY) std::memset(owned + base + rowStride, 0, rowStride);
                    if (last < 0) continue;
                    row.cubeFirst = first - 1;
                    row.cubeLast = last;
                    std::uint32_t edges = 0, triangles = 0;
                    const std::uint8_t* r0 = cls + base;
                    const std::uint8_t* r1 = r0 + rowStride;
                    const std::uint8_t* r2 = r0 + sliceStride;
                    const std::uint8_t* r3 = r2 + rowStride;
                    std::uint8_t* own = owned + base;
                    for (int ux = row.cubeFirst; ux <= row.cubeLast;) {
                        // Cubes ux .. ux+6 only touch points ux .. ux+7: when those are all
                        // outside or all inside (the block's values do not straddle the iso),
                        // there is nothing to do. Rows' owned edges lie within these four rows.
                        const std::uint64_t w0 = word(r0 + ux), w1 = word(r1 + ux),
                                            w2 = word(r2 + ux), w3 = word(r3 + ux);
                        if ((w0 | w1 | w2 | w3) == 0 || (w0 & w1 & w2 & w3) == kAllInside) {
                            ux += 7;
                            continue;
                        }
                        const std::size_t pi = base + ux;
                        const unsigned bits = ownedBits(cls, pi, rowStride, sliceStride);
                        own[ux] = static_cast<std::uint8_t>(bits);
                        edges += kBitCount3[bits];
                        triangles += cases[cubeCase(cls, pi, rowStride, sliceStride)].triangleCount;
                        ++ux;
                    }
                    row.edgeVertices = edges;
                    row.triangles = triangles;
                }
            }
        },
        4);

    // Pass 3: prefix sums give every row its output ranges (allocate once, no locks).
    std::size_t vertexTotal = 0, triangleTotal = 0;
    for (int uz = 0; uz < cubeRowsZ; ++uz)
        for (int uy = 0; uy < cubeRowsY; ++uy) {
            RowInfo& row = rows[g.rowIndex(uy, uz)];
            row.vertexBase = vertexTotal;
            row.triangleBase = triangleTotal;
            vertexTotal += row.edgeVertices;
            triangleTotal += row.triangles;
        }
    if (vertexTotal > std::numeric_limits<std::uint32_t>::max())
        throw Error("marching cubes: surface has too many vertices for 32-bit indices");

    Mesh mesh;
    mesh.positions.resize(vertexTotal);
    mesh.normals.resize(vertexTotal);
    mesh.triangles.resize(triangleTotal);

    Placement place;
    place.origin = volume.origin;
    place.toWorld = volume.direction * glm::dmat3(glm::dvec3(volume.spacing.x, 0, 0),
                                                  glm::dvec3(0, volume.spacing.y, 0),
                                                  glm::dvec3(0, 0, volume.spacing.z));
    place.gradToWorld =
        glm::mat3(volume.direction * glm::dmat3(glm::dvec3(1.0 / volume.spacing.x, 0, 0),
                                                glm::dvec3(0, 1.0 / volume.spacing.y, 0),
                                                glm::dvec3(0, 0, 1.0 / volume.spacing.z)));
    // A left-handed direction matrix mirrors the grid: flip the winding to stay outward.
    const bool mirrored = glm::determinant(volume.direction) < 0.0;

    // Pass 4: generate. Each cube row walks its four point rows in step, keeping for each the
    // id of the next owned edge vertex, so vertices shared with other rows are found without
    // any lookup table. Rows past the ROI own nothing (their `owned` bytes stay 0).
    parallelFor(
        cubeRowsZ, threads,
        [&](int begin, int end) {
            for (int uz = begin; uz < end; ++uz) {
                for (int uy = 0; uy < cubeRowsY; ++uy) {
                    const RowInfo& row = rows[g.rowIndex(uy, uz)];
                    if (row.cubeLast < row.cubeFirst) continue;
                    std::size_t cursor[4];
                    const std::uint8_t* own[4];
                    const std::uint8_t* clsRow[4];
                    int walkFirst = row.cubeFirst;
                    for (int q = 0; q < 4; ++q) {
                        const int qy = uy + (q & 1), qz = uz + (q >> 1);
                        own[q] = owned + g.pointIndex(0, qy, qz);
                        clsRow[q] = cls + g.pointIndex(0, qy, qz);
                        cursor[q] = 0;
                        if (qy >= cubeRowsY || qz >= cubeRowsZ) continue;
                        const RowInfo& r = rows[g.rowIndex(qy, qz)];
                        cursor[q] = r.vertexBase;
                        // Start where the earliest of the four rows has owned edges.
                        if (r.cubeLast >= r.cubeFirst) walkFirst = std::min(walkFirst, r.cubeFirst);
                    }
                    std::size_t triangleId = row.triangleBase;
                    for (int ux = walkFirst; ux <= row.cubeLast;) {
                        // Skip 7 cubes whose corners are all outside or all inside when no row
                        // owns an edge there (the other rows' edges may leave these four rows).
                        if ((word(own[0] + ux) | word(own[1] + ux) | word(own[2] + ux) |
                             word(own[3] + ux)) == 0) {
                            const std::uint64_t w0 = word(clsRow[0] + ux),
                                                w1 = word(clsRow[1] + ux),
                                                w2 = word(clsRow[2] + ux),
                                                w3 = word(clsRow[3] + ux);
                            if ((w0 | w1 | w2 | w3) == 0 || (w0 & w1 & w2 & w3) == kAllInside) {
                                ux += 7;
                                continue;
                            }
                        }
                        const unsigned bits[4] = {own[0][ux], own[1][ux], own[2][ux], own[3][ux]};
                        if (ux >= row.cubeFirst) {
                            const std::size_t pi = g.pointIndex(ux, uy, uz);
                            const mc::CubeCase& c =
                                cases[cubeCase(cls, pi, rowStride, sliceStride)];
                            // Owned edges of this point: create their vertices.
                            if (bits[0]) {
                                std::size_t id = cursor[0];
                                for (int axis = 0; axis < 3; ++axis) {
                                    if (!((bits[0] >> axis) & 1)) continue;
                                    const EdgeVertex v = makeEdgeVertex(g, place, ux, uy, uz, axis);
                                    mesh.positions[id] = v.position;
                                    mesh.normals[id] = v.normal;
                                    ++id;
                                }
                            }
                            if (c.triangleCount) {
                                std::uint32_t ref[12];
                                for (int e = 0; e < 12; ++e) {
                                    if (!((c.edgeMask >> e) & 1)) continue;
                                    const int axis = e >> 2, o0 = e & 1, o1 = (e >> 1) & 1;
                                    std::size_t id;
                                    if (axis == 0) {
                                        id = cursor[o0 +
                                                    2 * o1];  // x-edge: point ux of row (o0, o1)
                                    } else {
                                        // y-edge: point ux + o0 of row (0, o1), after the x bit;
                                        // z-edge: point ux + o0 of row (o1, 0), after x and y bits.
                                        const int q = axis == 1 ? 2 * o1 : o1;
                                        const unsigned before = axis == 1 ? 1u : 3u;
                                        id = cursor[q];
                                        if (o0) {
                                            id += kBitCount3[bits[q]];
                                            id += kBitCount3[own[q][ux + 1] & before];
                                        } else {
                                            id += kBitCount3[bits[q] & before];
                                        }
                                    }
                                    ref[e] = static_cast<std::uint32_t>(id);
                                }
                                for (int t = 0; t < c.triangleCount; ++t) {
                                    const auto& tri = c.triangles[t];
                                    glm::uvec3 out(ref[tri[0]], ref[tri[1]], ref[tri[2]]);
                                    if (mirrored) std::swap(out.y, out.z);
                                    mesh.triangles[triangleId++] = out;
                                }
                            }
                        }
                        for (int q = 0; q < 4; ++q) cursor[q] += kBitCount3[bits[q]];
                        ++ux;
                    }
                }
            }
        },
        4);

    const bool pick = options.onlyComponentRank || options.onlyComponentNear;
    if (options.labelComponents || options.keepLargestComponents > 0 || pick) {
        labelComponents(mesh);
        if (options.onlyComponentRank) {
            std::vector<bool> keep(static_cast<std::size_t>(*options.onlyComponentRank) + 1, false);
            keep.back() = true;
            keepComponents(mesh, keep);
        } else if (options.onlyComponentNear && !mesh.triangles.empty()) {
            std::vector<bool> keep(componentNearest(mesh, *options.onlyComponentNear) + 1, false);
            keep.back() = true;
            keepComponents(mesh, keep);
        }
        keepLargestComponents(mesh, options.keepLargestComponents);
    }
    return mesh;
}

}  // namespace fm
