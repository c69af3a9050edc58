#include "mesh/MarchingCubes.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include "core/Error.h"
#include "core/WorldLimits.h"
#include "core/LargeAllocation.h"
#include "core/Parallel.h"
#include "mesh/ClassifyRow.h"
#include "mesh/CubeLinks.h"
#include "mesh/MarchingCubesTable.h"
#include "mesh/MeshComponents.h"
#include "mesh/VertexForest.h"

namespace fm {
namespace {

// The hot loops handle 8 neighbouring cubes at once: 8 classification bytes read as one
// 64-bit word, one byte lane per cube (SWAR). Lane k is byte k in memory: little-endian.
static_assert(std::endian::native == std::endian::little,
              "marching cubes reads byte lanes of 64-bit words as little-endian");
constexpr std::uint64_t kLanes = 0x0101010101010101ull;  // 1 in every byte lane

inline std::uint64_t word(const std::uint8_t* p) {
    std::uint64_t w;
    std::memcpy(&w, p, sizeof w);
    return w;
}
inline unsigned lane(std::uint64_t w, int k) {
    return static_cast<unsigned>(w >> (8 * k)) & 0xffu;
}
// Per lane: the number of set bits of a 3-bit owned-edge mask (0..3).
inline std::uint64_t laneBitCounts(std::uint64_t owned) {
    return (owned & kLanes) + ((owned >> 1) & kLanes) + ((owned >> 2) & kLanes);
}

// Edge vertices stay this fraction of a voxel away from the corners: a value equal to the
// isovalue would otherwise put a vertex on a corner, where vertices of several edges coincide
// and triangles collapse to zero area. 1e-3 voxel is far above float resolution at CT world
// coordinates (~6e-5 mm at 800 mm) and far below any meaningful geometric error.
constexpr float kEdgeMargin = 1e-3f;

// The working grid: the ROI plus one virtual padding layer on every side. Local point
// u in [0, m + 1] per axis is voxel lo + u - 1; u = 0 and u = m + 1 are padding (below iso).
// Point rows are (uy, uz); cube (u) spans points u .. u + 1 and owns the three edges that
// leave point u in +x, +y, +z (so each edge is intersected once, by its owner).
// A row of the classification is p.x points plus at least 8 spare bytes, always 0 (outside):
// a word read for cubes ux .. ux + 7 (points up to ux + 8) then never leaves its row. One more
// slice of zeros after the last padding slice lets owned edges be derived for every point row
// (padding rows own nothing: all their neighbours in +y and +z are padding too, or zeros).
struct Grid {
    glm::ivec3 lo{0}, m{0}, p{0};  // ROI start (voxels), ROI size, padded size (m + 2)
    std::size_t rowStride = 0;     // bytes per point row, >= p.x + 8
    std::size_t sliceStride = 0;   // rowStride * p.y
    const Volume* volume = nullptr;
    float pad = 0.0f;
    float iso = 0.0f;

    std::size_t pointIndex(int ux, int uy, int uz) const {
        return static_cast<std::size_t>(ux) + rowStride * uy +
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
    std::uint32_t vertexBase = 0;
    std::size_t triangleBase = 0;
};

// The case table in the layout the generate loop wants: triangle corners as one flat list.
struct PackedCase {
    std::uint8_t triangleCount = 0;
    std::uint8_t edges[3 * mc::kMaxTriangles] = {};
};
struct PackedCases {
    std::array<PackedCase, 256> asIs, mirrored;  // mirrored: winding flipped
};

const PackedCases& packedCases() {
    static const PackedCases table = [] {
        PackedCases t;
        const auto& cases = mc::cubeCases();
        for (int c = 0; c < 256; ++c) {
            t.asIs[c].triangleCount = t.mirrored[c].triangleCount = cases[c].triangleCount;
            for (int i = 0; i < cases[c].triangleCount; ++i) {
                const auto& tri = cases[c].triangles[i];
                for (int v = 0; v < 3; ++v) t.asIs[c].edges[3 * i + v] = tri[v];
                t.mirrored[c].edges[3 * i] = tri[0];
                t.mirrored[c].edges[3 * i + 1] = tri[2];
                t.mirrored[c].edges[3 * i + 2] = tri[1];
            }
        }
        return t;
    }();
    return table;
}

// Case numbers of cubes ux .. ux + 7 of a cube row, one per byte lane; r0..r3 are the
// classification rows (uy, uz), (uy + 1, uz), (uy, uz + 1), (uy + 1, uz + 1). Corner c of a
// cube sits at (c & 1, (c >> 1) & 1, c >> 2) and is bit c of its case.
inline std::uint64_t caseWord(const std::uint8_t* r0, const std::uint8_t* r1,
                              const std::uint8_t* r2, const std::uint8_t* r3, int ux) {
    return word(r0 + ux) | (word(r0 + ux + 1) << 1) | (word(r1 + ux) << 2) |
           (word(r1 + ux + 1) << 3) | (word(r2 + ux) << 4) | (word(r2 + ux + 1) << 5) |
           (word(r3 + ux) << 6) | (word(r3 + ux + 1) << 7);
}

// Crossed edges owned by points ux .. ux + 7 of point row `row`, one 3-bit mask per byte lane:
// bit 0 the x edge to the next point, bit 1 the y edge to the next row, bit 2 the z edge to the
// next slice. Derived from the classification whenever needed instead of stored: a stored copy
// would be another volume-sized array to fault in, write and read back.
inline std::uint64_t ownedWord(const std::uint8_t* row, std::size_t rowStride,
                               std::size_t sliceStride, int ux) {
    const std::uint64_t a = word(row + ux);
    return (a ^ word(row + ux + 1)) | ((a ^ word(row + rowStride + ux)) << 1) |
           ((a ^ word(row + sliceStride + ux)) << 2);
}

// Vertices on crossed edges, in world millimetres with outward unit normals.
struct VertexMaker {
    const Grid* g = nullptr;
    const float* values = nullptr;
    std::ptrdiff_t sy = 0, sz = 0;  // volume strides (voxels) in y and z
    glm::dmat3 toWorld;             // direction * diag(spacing)
    glm::mat3 gradToWorld;          // direction * diag(1 / spacing)
    glm::dvec3 origin;
    glm::vec3* positions = nullptr;
    glm::vec3* normals = nullptr;

    // Vertex `id` on the edge leaving local point (ux, uy, uz) along Axis. `rowInterior`: the
    // central differences at both ends stay inside the ROI in y and z (x is checked here).
    // Normals are the interpolated central-difference gradient, negated (pointing to lower
    // values: outward).
    template <int Axis>
    void make(int ux, int uy, int uz, std::uint32_t id, bool rowInterior) const {
        float v0, v1;
        glm::vec3 g0, g1;
        if (rowInterior && ux >= 2 && ux + (Axis == 0) <= g->m.x - 1) {
            constexpr std::ptrdiff_t sx = 1;
            const std::ptrdiff_t step = Axis == 0 ? sx : Axis == 1 ? sy : sz;
            const float* p0 =
                values + (g->lo.x + ux - 1) + sy * (g->lo.y + uy - 1) + sz * (g->lo.z + uz - 1);
            const float* p1 = p0 + step;
            v0 = p0[0];
            v1 = p1[0];
            g0 = glm::vec3(p0[sx] - p0[-sx], p0[sy] - p0[-sy], p0[sz] - p0[-sz]);
            g1 = glm::vec3(p1[sx] - p1[-sx], p1[sy] - p1[-sy], p1[sz] - p1[-sz]);
        } else {
            const int bx = ux + (Axis == 0), by = uy + (Axis == 1), bz = uz + (Axis == 2);
            v0 = g->value(ux, uy, uz);
            v1 = g->value(bx, by, bz);
            g0 = glm::vec3(g->value(ux + 1, uy, uz) - g->value(ux - 1, uy, uz),
                           g->value(ux, uy + 1, uz) - g->value(ux, uy - 1, uz),
                           g->value(ux, uy, uz + 1) - g->value(ux, uy, uz - 1));
            g1 = glm::vec3(g->value(bx + 1, by, bz) - g->value(bx - 1, by, bz),
                           g->value(bx, by + 1, bz) - g->value(bx, by - 1, bz),
                           g->value(bx, by, bz + 1) - g->value(bx, by, bz - 1));
        }
        float t = (g->iso - v0) / (v1 - v0);  // v0 and v1 lie on different sides: v1 != v0
        // Written so that NaN (a NaN or infinite voxel value) lands on the margin, not in the mesh.
        t = t > kEdgeMargin ? (t < 1.0f - kEdgeMargin ? t : 1.0f - kEdgeMargin) : kEdgeMargin;
        glm::dvec3 voxel(g->lo.x + ux - 1, g->lo.y + uy - 1, g->lo.z + uz - 1);
        voxel[Axis] += t;
        positions[id] = glm::vec3(origin + toWorld * voxel);
        // Twice the gradient (central differences without the 1/2): only the direction matters.
        glm::vec3 n = -(gradToWorld * (g0 + t * (g1 - g0)));
        float len2 = glm::dot(n, n);
        if (!(len2 > 1e-30f) || !std::isfinite(len2)) {
            // Flat gradient (plateaus): point from the inside corner to the outside one.
            glm::vec3 axisDir(0.0f);
            axisDir[Axis] = v0 >= g->iso ? 1.0f : -1.0f;
            n = gradToWorld * axisDir;
            len2 = glm::dot(n, n);
        }
        normals[id] = n / std::sqrt(len2);
    }
};

// Cube-slice boundaries for the generate pass: `chunks` chunks cut by work (triangles plus
// twice the vertices, known from the row counts), not by slice count, since a surface is rarely
// spread evenly over the slices; and shrinking, chunk c ending where 1 - (1 - (c+1)/chunks)^2
// of the work is done, so that the threads, taking chunks as they come free, end within a
// small chunk of each other (DICOM series, 2 threads: generate 4.5-5.0 -> 4.2 ms). The split
// depends on the thread count; the mesh does not.
std::vector<int> balancedSliceChunks(const std::vector<RowInfo>& rows, const Grid& g,
                                     int cubeRowsY, int cubeRowsZ, int chunks) {
    std::vector<double> before(static_cast<std::size_t>(cubeRowsZ) + 1, 0.0);
    for (int uz = 0; uz < cubeRowsZ; ++uz) {
        double work = 0.0;
        for (int uy = 0; uy < cubeRowsY; ++uy) {
            const RowInfo& row = rows[g.rowIndex(uy, uz)];
            work += row.triangles + 2.0 * row.edgeVertices;
        }
        before[uz + 1] = before[uz] + work;
    }
    std::vector<int> bounds{0};
    for (int c = 1; c < chunks; ++c) {
        const double rest = 1.0 - static_cast<double>(c) / chunks;
        const double share = before.back() * (1.0 - rest * rest);
        const int slice = static_cast<int>(
            std::lower_bound(before.begin(), before.end(), share) - before.begin());
        if (slice > bounds.back() && slice < cubeRowsZ) bounds.push_back(slice);
    }
    bounds.push_back(cubeRowsZ);
    return bounds;
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
    if (o.onlyComponentNear)
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite((*o.onlyComponentNear)[a]) ||
                std::abs((*o.onlyComponentNear)[a]) > kMaxWorldMm)
                throw Error("marching cubes: the point to keep the component nearest to must be "
                            "finite, within " + std::to_string(kMaxWorldMm) + " mm (got " +
                            std::to_string((*o.onlyComponentNear)[a]) + ")");
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

Mesh marchingCubes(const Volume& volume, const MarchingCubesOptions& options,
                   std::size_t* componentCount) {
    glm::ivec3 lo, hi;
    checkOptions(volume, options, lo, hi);
    const PackedCases& packed = packedCases();
    const int threads = options.threads <= 0 ? defaultThreadCount() : options.threads;

    Grid g;
    g.volume = &volume;
    g.lo = lo;
    g.m = hi - lo + 1;
    g.p = g.m + 2;
    g.rowStride = (static_cast<std::size_t>(g.p.x) + 8 + 7) & ~std::size_t{7};
    g.sliceStride = g.rowStride * g.p.y;
    g.iso = static_cast<float>(options.isoValue);
    const std::size_t rowStride = g.rowStride;
    const std::size_t sliceStride = g.sliceStride;

    // Pass 1: classify every ROI voxel (inside = value >= iso), note where each row has inside
    // points, and the ROI minimum for the padding value. Padding stays 0 (outside). It runs
    // in one loop with pass 2 (below).
    // The array is left uninitialised and written in full by the parallel pass: a zeroing
    // memset up front would touch every page twice (it cost ~20% on large CTs).
    const std::size_t byteCount = sliceStride * (g.p.z + 1);
    const LargeBuffer<std::uint8_t> clsStore = makeLargeBuffer<std::uint8_t>(byteCount);
    std::uint8_t* const cls = clsStore.get();
    // Padding slices and the slice of zeros after them.
    std::memset(cls, 0, sliceStride);
    std::memset(cls + sliceStride * (g.p.z - 1), 0, 2 * sliceStride);
    std::vector<RowInfo> rows(static_cast<std::size_t>(g.p.y) * g.p.z);
    std::vector<float> layerMin(g.p.z, std::numeric_limits<float>::infinity());
    const float iso = g.iso;
    auto classifySlice = [&](int uz) {
        float lowest = std::numeric_limits<float>::infinity();
        // Padding rows of this slice.
        std::memset(&cls[g.pointIndex(0, 0, uz)], 0, rowStride);
        std::memset(&cls[g.pointIndex(0, g.p.y - 1, uz)], 0, rowStride);
        for (int uy = 1; uy <= g.m.y; ++uy) {
            const float* src =
                &volume.values[volume.index(lo.x, lo.y + uy - 1, lo.z + uz - 1)];
            std::uint8_t* row = &cls[g.pointIndex(0, uy, uz)];
            std::uint8_t* dst = row + 1;
            const int width = g.m.x;
            row[0] = 0;
            const float rowLowest = mc::classifyRow(src, dst, width, iso);
            lowest = rowLowest < lowest ? rowLowest : lowest;
            std::memset(dst + width, 0, rowStride - 1 - width);
            const void* firstInside = std::memchr(dst, 1, width);
            if (!firstInside) continue;
            int last = width - 1;
            while (!dst[last]) --last;
            RowInfo& info = rows[g.rowIndex(uy, uz)];
            info.insideFirst =
                static_cast<int>(static_cast<const std::uint8_t*>(firstInside) - dst) + 1;
            info.insideLast = last + 1;
        }
        layerMin[uz] = lowest;
    };

    // Pass 2: per cube row, the cubes worth visiting (those near an inside point of the four
    // point rows it touches: the rest are all outside and are skipped), the crossed edges its
    // point row owns, and its triangle count. 8 cubes per step; a step whose cubes are all
    // outside or all inside (the block's values do not straddle the iso) costs 8 loads.
    const int cubeRowsY = g.m.y + 1, cubeRowsZ = g.m.z + 1;
    auto countCubeSlice = [&](int uz) {
        for (int uy = 0; uy < cubeRowsY; ++uy) {
            RowInfo& row = rows[g.rowIndex(uy, uz)];
            int first = std::numeric_limits<int>::max(), last = -1;
            for (int dz = 0; dz < 2; ++dz)
                for (int dy = 0; dy < 2; ++dy) {
                    const RowInfo& q = rows[g.rowIndex(uy + dy, uz + dz)];
                    first = std::min(first, q.insideFirst);
                    last = std::max(last, q.insideLast);
                }
            if (last < 0) continue;
            const std::size_t base = g.pointIndex(0, uy, uz);
            row.cubeFirst = first - 1;
            row.cubeLast = last;
            std::uint32_t edges = 0, triangles = 0;
            const std::uint8_t* r0 = cls + base;
            const std::uint8_t* r1 = r0 + rowStride;
            const std::uint8_t* r2 = r0 + sliceStride;
            const std::uint8_t* r3 = r2 + rowStride;
            for (int ux = row.cubeFirst; ux <= row.cubeLast; ux += 8) {
                const std::uint64_t c = caseWord(r0, r1, r2, r3, ux);
                if (c == 0 || c == ~std::uint64_t{0}) continue;
                const std::uint64_t o = ownedWord(r0, rowStride, sliceStride, ux);
                edges += static_cast<std::uint32_t>((laneBitCounts(o) * kLanes) >> 56);
                for (int k = 0; k < 8; ++k)
                    triangles += packed.asIs[lane(c, k)].triangleCount;
            }
            row.edgeVertices = edges;
            row.triangles = triangles;
        }
    };

    // Passes 1 and 2 run together: a chunk of point slices counts each cube slice as soon as
    // its two point slices are classified, while they are in the cache. The first cube slice
    // of a chunk also needs the previous chunk's last point slice: those are counted after.
    std::vector<std::uint8_t> counted(static_cast<std::size_t>(cubeRowsZ), 0);
    parallelFor(
        g.m.z, threads,
        [&](int begin, int end) {
            for (int uz = begin + 1; uz <= end; ++uz) {
                classifySlice(uz);
                if (uz - 1 > begin || begin == 0) {  // point slice 0 is padding: ready
                    countCubeSlice(uz - 1);
                    counted[uz - 1] = 1;
                }
            }
            if (end == g.m.z) {  // the last cube slice reaches into padding only
                countCubeSlice(end);
                counted[end] = 1;
            }
        },
        4);
    std::vector<int> chunkStarts;
    for (int uz = 0; uz < cubeRowsZ; ++uz)
        if (!counted[uz]) chunkStarts.push_back(uz);
    parallelFor(static_cast<int>(chunkStarts.size()), threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) countCubeSlice(chunkStarts[i]);
    });
    if (options.padValue) {
        g.pad = static_cast<float>(*options.padValue);
    } else {
        const float lowest = *std::min_element(layerMin.begin(), layerMin.end());
        g.pad = lowest < iso ? lowest : iso - 1.0f;
    }

    // Pass 3: prefix sums give every row its output ranges (allocate once, no locks).
    std::size_t vertexTotal = 0, triangleTotal = 0;
    for (int uz = 0; uz < cubeRowsZ; ++uz)
        for (int uy = 0; uy < cubeRowsY; ++uy) {
            RowInfo& row = rows[g.rowIndex(uy, uz)];
            row.vertexBase = static_cast<std::uint32_t>(vertexTotal);
            row.triangleBase = triangleTotal;
            vertexTotal += row.edgeVertices;
            triangleTotal += row.triangles;
            if (vertexTotal > std::numeric_limits<std::uint32_t>::max())
                throw Error("marching cubes: surface has too many vertices for 32-bit indices");
        }

    Mesh mesh;
    mesh.positions.resize(vertexTotal);
    mesh.normals.resize(vertexTotal);
    mesh.triangles.resize(triangleTotal);

    VertexMaker maker;
    maker.g = &g;
    maker.values = volume.values.data();
    maker.sy = volume.dims.x;
    maker.sz = static_cast<std::ptrdiff_t>(volume.dims.x) * volume.dims.y;
    maker.origin = volume.origin;
    maker.toWorld = volume.direction * glm::dmat3(glm::dvec3(volume.spacing.x, 0, 0),
                                                  glm::dvec3(0, volume.spacing.y, 0),
                                                  glm::dvec3(0, 0, volume.spacing.z));
    maker.gradToWorld =
        glm::mat3(volume.direction * glm::dmat3(glm::dvec3(1.0 / volume.spacing.x, 0, 0),
                                                glm::dvec3(0, 1.0 / volume.spacing.y, 0),
                                                glm::dvec3(0, 0, 1.0 / volume.spacing.z)));
    maker.positions = mesh.positions.data();
    maker.normals = mesh.normals.data();
    // A left-handed direction matrix mirrors the grid: flip the winding to stay outward.
    const auto& table = glm::determinant(volume.direction) < 0.0 ? packed.mirrored : packed.asIs;
    glm::uvec3* const outTriangles = mesh.triangles.data();

    // Components: the generate pass unites, per cube, the loop segments on its upper faces
    // (mesh/CubeLinks.h) while the cube's vertex ids are at hand. A chunk of cube slices
    // [begin, end) only links vertices of the point slices it owns, [begin, end): the cubes of
    // its last slice reach into point slice `end` (the next chunk's), so their segments that
    // touch it are kept for a serial pass afterwards and no two threads write the same entries.
    // Labelling the triangles (ranks) is only done when asked for or needed to choose
    // components; a count alone comes from the forest.
    const bool pick = options.onlyComponentRank || options.onlyComponentNear;
    const bool labelTriangles =
        options.labelComponents || options.keepLargestComponents > 0 || pick;
    const bool label = labelTriangles || componentCount != nullptr;
    const auto& links = mc::cubeLinks();
    MeshArray<std::uint32_t> forest(label ? vertexTotal : 0);
    using Segment = std::pair<std::uint32_t, std::uint32_t>;
    std::vector<std::vector<Segment>> crossing(label ? cubeRowsZ : 0);  // by chunk begin
    auto slicesFirstVertex = [&](int uz) -> std::uint32_t {
        return uz < cubeRowsZ ? rows[g.rowIndex(0, uz)].vertexBase
                              : static_cast<std::uint32_t>(vertexTotal);
    };

    // Pass 4: generate, per cube row: first the vertices of the edges its point row owns, in
    // point order and x, y, z within a point (the order pass 3 numbered them in), then its
    // triangles. The cube row walks its four point rows in step, keeping for each the id of
    // its next owned vertex, so vertices owned by other rows are found without a lookup
    // table.
    auto generateSlices = [&](int begin, int end) {
        const std::uint32_t ownFirst = slicesFirstVertex(begin);
        const std::uint32_t ownEnd = slicesFirstVertex(end);
        if (label)
            std::iota(forest.begin() + ownFirst, forest.begin() + ownEnd, ownFirst);
        std::uint32_t* const parent = forest.data();
        // Collected here, not in crossing[begin] directly: the chunks' vector headers share
        // cache lines, and growing them from two threads made them bounce between cores.
        std::vector<Segment> deferred;
        for (int uz = begin; uz < end; ++uz) {
            const bool defer = label && uz == end - 1 && end < cubeRowsZ;
            const bool unite = label && !defer;
            for (int uy = 0; uy < cubeRowsY; ++uy) {
                const RowInfo& row = rows[g.rowIndex(uy, uz)];
                if (row.cubeLast < row.cubeFirst) continue;
                const std::size_t base = g.pointIndex(0, uy, uz);
                {
                    // The volume row the z-edge gradients two rows on will read first: it
                    // comes from memory, the other rows they read are already cached.
                    const int vy = g.lo.y + uy + 2, vz = g.lo.z + uz + 1;
                    if (vy < volume.dims.y && vz < volume.dims.z) {
                        const float* pf = &volume.values[volume.index(g.lo.x, vy, vz)];
                        const int xEnd = std::min(row.cubeLast + 1, g.m.x - 1);
                        for (int x = std::max(row.cubeFirst - 2, 0); x <= xEnd; x += 16)
                            __builtin_prefetch(pf + x);  // one 64-byte line per 16 floats
                    }
                }
                if (row.edgeVertices) {
                    const std::uint8_t* r0 = cls + base;
                    // Central differences at both edge ends stay inside the ROI in y, z.
                    const bool yz = uy >= 2 && uz >= 2;
                    const bool interiorX = yz && uy <= g.m.y - 1 && uz <= g.m.z - 1;
                    const bool interiorY = yz && uy + 1 <= g.m.y - 1 && uz <= g.m.z - 1;
                    const bool interiorZ = yz && uy <= g.m.y - 1 && uz + 1 <= g.m.z - 1;
                    std::uint32_t id = row.vertexBase;
                    for (int ux = row.cubeFirst; ux <= row.cubeLast; ux += 8) {
                        std::uint64_t w = ownedWord(r0, rowStride, sliceStride, ux);
                        while (w) {
                            const int k = std::countr_zero(w) >> 3;
                            const unsigned bits = lane(w, k);
                            w &= ~(std::uint64_t{0xff} << (8 * k));
                            if (bits & 1) maker.make<0>(ux + k, uy, uz, id++, interiorX);
                            if (bits & 2) maker.make<1>(ux + k, uy, uz, id++, interiorY);
                            if (bits & 4) maker.make<2>(ux + k, uy, uz, id++, interiorZ);
                        }
                    }
                }
                if (row.triangles == 0) continue;

                // Triangles. The four point rows q = dy + 2 dz hold the cube row's edges.
                const std::uint8_t* r0 = cls + base;
                const std::uint8_t* r1 = r0 + rowStride;
                const std::uint8_t* r2 = r0 + sliceStride;
                const std::uint8_t* r3 = r2 + rowStride;
                const std::uint8_t* pointRow[4];
                std::uint32_t cursor[4];
                int walkFirst = row.cubeFirst;
                for (int q = 0; q < 4; ++q) {
                    const int qy = uy + (q & 1), qz = uz + (q >> 1);
                    pointRow[q] = cls + g.pointIndex(0, qy, qz);
                    cursor[q] = 0;
                    if (qy >= cubeRowsY || qz >= cubeRowsZ) continue;  // owns nothing
                    const RowInfo& r = rows[g.rowIndex(qy, qz)];
                    cursor[q] = r.vertexBase;
                    // Start where the earliest of the four rows has owned edges.
                    if (r.edgeVertices) walkFirst = std::min(walkFirst, r.cubeFirst);
                }
                std::size_t triangleId = row.triangleBase;
                for (int ux = walkFirst; ux <= row.cubeLast; ux += 8) {
                    std::uint64_t o[4];
                    for (int q = 0; q < 4; ++q)
                        o[q] = ownedWord(pointRow[q], rowStride, sliceStride, ux);
                    const std::uint64_t c = caseWord(r0, r1, r2, r3, ux);
                    if (c == 0 || c == ~std::uint64_t{0}) {
                        // No triangles here, but rows 1-3 may own edges leaving the four
                        // rows: step their cursors over them.
                        for (int q = 0; q < 4; ++q)
                            if (o[q])
                                cursor[q] += static_cast<std::uint32_t>(
                                    (laneBitCounts(o[q]) * kLanes) >> 56);
                        continue;
                    }
                    // Per lane: owned vertices of each row up to and including that point.
                    std::uint64_t upTo[4];
                    for (int q = 0; q < 4; ++q) upTo[q] = laneBitCounts(o[q]) * kLanes;
                    // Owned edges of the next point (y and z edges at the cube's far x).
                    const std::uint64_t next0 = ownedWord(r0, rowStride, sliceStride, ux + 1),
                                        next1 = ownedWord(r1, rowStride, sliceStride, ux + 1),
                                        next2 = ownedWord(r2, rowStride, sliceStride, ux + 1);
                    for (int k = 0; k < 8; ++k) {
                        const PackedCase& pc = table[lane(c, k)];
                        if (!pc.triangleCount) continue;
                        // Ids of the first owned vertex of point ux + k (before) and of
                        // point ux + k + 1 (after) in rows 0, 1 and 2; row 3 needs before.
                        std::uint32_t before[4], after[3];
                        for (int q = 0; q < 4; ++q)
                            before[q] = cursor[q] + (k ? lane(upTo[q], k - 1) : 0u);
                        for (int q = 0; q < 3; ++q) after[q] = cursor[q] + lane(upTo[q], k);
                        const unsigned b0 = lane(o[0], k), b1 = lane(o[1], k),
                                       b2 = lane(o[2], k);
                        const unsigned n0 = lane(next0, k), n1 = lane(next1, k),
                                       n2 = lane(next2, k);
                        // Edge e: axis e / 4 from the corner offset by bits of e % 4 in
                        // the other two axes (lower axis first). Within a point the owned
                        // vertices come in the order x, y, z.
                        std::uint32_t ref[12];
                        ref[0] = before[0];
                        ref[1] = before[1];
                        ref[2] = before[2];
                        ref[3] = before[3];
                        ref[4] = before[0] + (b0 & 1);
                        ref[5] = after[0] + (n0 & 1);
                        ref[6] = before[2] + (b2 & 1);
                        ref[7] = after[2] + (n2 & 1);
                        ref[8] = before[0] + (b0 & 1) + ((b0 >> 1) & 1);
                        ref[9] = after[0] + (n0 & 1) + ((n0 >> 1) & 1);
                        ref[10] = before[1] + (b1 & 1) + ((b1 >> 1) & 1);
                        ref[11] = after[1] + (n1 & 1) + ((n1 >> 1) & 1);
                        const std::uint8_t* e = pc.edges;
                        for (int t = 0; t < pc.triangleCount; ++t, e += 3)
                            outTriangles[triangleId++] =
                                glm::uvec3(ref[e[0]], ref[e[1]], ref[e[2]]);
                        if (unite) {
                            const mc::CubeLinks& l = links[lane(c, k)];
                            std::uint32_t root = 0;
                            for (int i = 0; i < l.count; ++i) {
                                const std::uint8_t step = l.steps[i];
                                const std::uint32_t v = ref[step & 15];
                                const std::uint32_t r = step & mc::CubeLinks::kFirstCube
                                                            ? v
                                                            : forestRoot(parent, v);
                                if (step & mc::CubeLinks::kPathStart) {
                                    root = r;
                                } else if (r > root) {
                                    parent[r] = root;
                                } else if (r < root) {
                                    parent[root] = r;
                                    root = r;
                                }
                            }
                        } else if (defer) {
                            const mc::CubeLinks& l = links[lane(c, k)];
                            for (int i = 1; i < l.count; ++i) {
                                if (l.steps[i] & mc::CubeLinks::kPathStart) continue;
                                const std::uint32_t a = ref[l.steps[i - 1] & 15],
                                                    b = ref[l.steps[i] & 15];
                                if (a < ownEnd && b < ownEnd)
                                    forestUnite(parent, a, b);
                                else
                                    deferred.emplace_back(a, b);
                            }
                        }
                    }
                    for (int q = 0; q < 4; ++q)
                        cursor[q] += static_cast<std::uint32_t>(upTo[q] >> 56);
                }
            }
        }
        if (!deferred.empty()) crossing[begin] = std::move(deferred);
    };
    // One chunk on one thread (nothing deferred); else 4 per thread.
    const std::vector<int> chunkBounds = balancedSliceChunks(
        rows, g, cubeRowsY, cubeRowsZ, threads == 1 ? 1 : 4 * threads);
    const int chunkCount = static_cast<int>(chunkBounds.size()) - 1;
    parallelFor(
        chunkCount, threads,
        [&](int first, int last) {
            for (int c = first; c < last; ++c) generateSlices(chunkBounds[c], chunkBounds[c + 1]);
        },
        chunkCount);

    if (label) {
        for (const auto& chunk : crossing)
            for (const auto& [a, b] : chunk) forestUnite(forest.data(), a, b);
        if (!labelTriangles) {
            *componentCount = countForestRoots(forest.data(), vertexTotal, threads);
            return mesh;
        }
        labelComponentsFromForest(mesh, forest.data(), threads);
        if (options.onlyComponentRank) {
            std::vector<bool> keep(static_cast<std::size_t>(*options.onlyComponentRank) + 1, false);
            keep.back() = true;
            keepComponents(mesh, keep, threads);
        } else if (options.onlyComponentNear && !mesh.triangles.empty()) {
            std::vector<bool> keep(componentNearest(mesh, *options.onlyComponentNear) + 1, false);
            keep.back() = true;
            keepComponents(mesh, keep, threads);
        }
        keepLargestComponents(mesh, options.keepLargestComponents, threads);
        if (componentCount) {
            const std::vector<std::size_t> sizes = componentSizes(mesh);
            *componentCount = static_cast<std::size_t>(
                std::count_if(sizes.begin(), sizes.end(), [](std::size_t n) { return n > 0; }));
        }
    }
    return mesh;
}

}  // namespace fm
