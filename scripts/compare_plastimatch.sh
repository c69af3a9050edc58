#!/usr/bin/env bash
# Compare `fluoromatch drr` with `plastimatch drr` (the established CPU tool, exact Siddon mode)
# on the same volume file and the same geometries: render time per view and pixel agreement.
# Installs the Debian package plastimatch if it is missing (it is not needed for anything else).
#
#   bash scripts/compare_plastimatch.sh [options]
#     --fluoromatch PATH   executable (default: build/app/fluoromatch)
#     --volume SPEC        volume for both tools (default: phantom:knee), written once as .mha
#     --size WxH           film pixels of the scene (default: the scene default, 256x256)
#     --repeat N           alternating runs per view and tool; the fastest render counts (default: 7)
#     --threads N          threads for both tools (default: 2; plastimatch via OMP_NUM_THREADS)
#     --keep DIR           keep the images and geometry files in DIR
#
# Units. plastimatch divides line integrals by 10 (mm -> cm). Its default HU conversion is
# mu = 0.022 (1 + HU/1000) per mm for HU > -800 and 0 otherwise; ours is mu_water (1 + HU/1000)
# with mu_water = kMuWaterPerMm (engine/drr/Drr.h). So in "mu" mode we render with
# --threshold -799.99997 (our threshold keeps stored >= level; this keeps exactly the float
# values > -800, also the many voxels at exactly -800 of integer CTs) and expect
# ours = plastimatch * 10 * kMuWaterPerMm / 0.022.
# plastimatch ignores direction cosines: it gets an identity-axes copy of the volume (below). In "raw" mode (--values raw vs -P none) we expect
# ours = plastimatch * 10.
#
# Geometry mapping (checked against plastimatch 1.9.4's source and output): --nrm is the unit
# detector normal towards the source, the camera sits at isocenter + sad * nrm, the detector
# centre at camera - sid * nrm, columns run along vup x nrm (= our u), rows along our v
# (vup = -v). Despite its help text ("row col"), 1.9.4 reads -r and -z as "columns rows" (the
# first number is the image width): verified with non-square detectors.
#
# Agreement is reported over all pixels and over "interior" rays: rays that cross the volume
# and whose entry and exit voxels on its faces are zero after conversion. plastimatch's exact tracer is short
# by up to one voxel where a ray enters or leaves the volume through non-zero voxels (the
# knee's tissue is cut by the top and bottom faces of the field; in raw mode every face is
# -1000 HU air), so the all-pixel figures measure plastimatch's boundary handling and the
# interior figures measure the tracers themselves.
set -euo pipefail
cd "$(dirname "$0")/.."

FM=build/app/fluoromatch
VOLUME=phantom:knee
SIZE=""
REPEAT=7
THREADS=2
KEEP=""
while [ $# -gt 0 ]; do
    case "$1" in
        --fluoromatch) FM=$2; shift 2 ;;
        --volume) VOLUME=$2; shift 2 ;;
        --size) SIZE=$2; shift 2 ;;
        --repeat) REPEAT=$2; shift 2 ;;
        --threads) THREADS=$2; shift 2 ;;
        --keep) KEEP=$2; shift 2 ;;
        -h|--help) sed -n '2,30p' "$0"; exit 0 ;;
        *) echo "compare_plastimatch: unknown option $1" >&2; exit 2 ;;
    esac
done

if [ ! -x "$FM" ]; then
    echo "compare_plastimatch: $FM not found; build first (cmake --build build)" >&2
    exit 1
fi
FM=$(realpath "$FM")
if ! "$FM" drr --help >/dev/null 2>&1; then
    echo "compare_plastimatch: this fluoromatch has no drr command yet" >&2
    exit 1
fi
if ! command -v plastimatch >/dev/null; then
    echo "compare_plastimatch: installing plastimatch (Debian package)"
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends plastimatch
fi
MU_WATER=$(sed -n 's/.*kMuWaterPerMm = \([0-9.eE+-]*\);.*/\1/p' engine/drr/Drr.h)
[ -n "$MU_WATER" ] || { echo "compare_plastimatch: kMuWaterPerMm not found in Drr.h" >&2; exit 1; }

if [ -n "$KEEP" ]; then
    mkdir -p "$KEEP"
    WORK=$(realpath "$KEEP")
else
    WORK=$(mktemp -d)
    trap 'rm -rf "$WORK"' EXIT
fi

# Python helper (standard library only): geometry -> plastimatch options, and image comparison.
cat > "$WORK/helper.py" <<'PY'
import json, math, struct, sys, zlib

def read_mha(path):
    data = open(path, 'rb').read()
    marker = b'ElementDataFile = LOCAL\n'
    at = data.index(marker) + len(marker)
    header = dict(line.split(' = ', 1) for line in data[:at].decode().strip().split('\n'))
    if header['ElementType'] != 'MET_FLOAT':
        sys.exit('%s: expected float32' % path)
    dims = [int(x) for x in header['DimSize'].split()]
    body = data[at:]
    if header.get('CompressedData', 'False') == 'True':
        body = zlib.decompress(body)
    n = 1
    for d in dims:
        n *= d
    values = struct.unpack('<%df' % n, body[:4 * n])
    spacing = [float(x) for x in header['ElementSpacing'].split()]
    origin = [float(x) for x in header['Offset'].split()]
    m = [float(x) for x in header.get('TransformMatrix', '1 0 0 0 1 0 0 0 1').split()]
    # MetaImage TransformMatrix lists the axis directions one after the other.
    axes = [m[0:3], m[3:6], m[6:9]]
    return dims, spacing, origin, axes, values

def axis_aligned_copy(in_path, out_path):
    # plastimatch 1.9.4's DRR ignores the direction cosines (it traces as if the axes were
    # identity), so a volume stored along other axes (RAS-stored NIfTIs such as example_ct:
    # direction diag(-1,-1,1) in LPS) is handed to it flipped into identity axes: the same
    # voxels at the same world positions, voxel order reversed along every negative axis.
    # Exact (a reordering). Other direction matrices (permutations, oblique) are refused.
    import array
    dims, spacing, origin, axes, values = read_mha(in_path)
    flip = []
    for a in range(3):
        unit = [0.0, 0.0, 0.0]
        unit[a] = 1.0
        if all(abs(axes[a][b] - unit[b]) < 1e-9 for b in range(3)):
            flip.append(False)
        elif all(abs(axes[a][b] + unit[b]) < 1e-9 for b in range(3)):
            flip.append(True)
        else:
            flip = None
            break
    if flip is None:
        # An oblique grid (the GE gantry-tilt series, resampled along its tilted slices):
        # plastimatch cannot place it, so both tools get this copy with identity axes, the
        # same voxels on the same grid, and render the same geometry around it.
        flip = [False, False, False]
        print('oblique')
    nx, ny, nz = dims
    src = array.array('f', values)
    out = array.array('f', bytes(4 * nx * ny * nz))
    for k in range(nz):
        sk = nz - 1 - k if flip[2] else k
        for j in range(ny):
            sj = ny - 1 - j if flip[1] else j
            row = src[nx * (sj + ny * sk):nx * (sj + ny * sk + 1)]
            if flip[0]:
                row.reverse()
            out[nx * (j + ny * k):nx * (j + ny * k + 1)] = row
    # New voxel (0,0,0) is the old voxel at the far end of every flipped axis.
    new_origin = list(origin)
    for a in range(3):
        if flip[a]:
            new_origin = add(new_origin, scale(axes[a], (dims[a] - 1) * spacing[a]))
    header = ('ObjectType = Image\nNDims = 3\nBinaryData = True\n'
              'BinaryDataByteOrderMSB = False\nCompressedData = False\n'
              'TransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = %s\nElementSpacing = %s\n'
              'DimSize = %d %d %d\nElementType = MET_FLOAT\nElementDataFile = LOCAL\n'
              % (' '.join('%.17g' % x for x in new_origin),
                 ' '.join('%.17g' % x for x in spacing), nx, ny, nz))
    if sys.byteorder != 'little':
        out.byteswap()
    with open(out_path, 'wb') as f:
        f.write(header.encode())
        f.write(out.tobytes())

def sub(a, b): return [a[i] - b[i] for i in range(3)]
def dot(a, b): return sum(a[i] * b[i] for i in range(3))
def cross(a, b): return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
def scale(a, s): return [x * s for x in a]
def add(a, b): return [a[i] + b[i] for i in range(3)]

def plastimatch_args(geometry_path):
    g = json.load(open(geometry_path))
    d = g['detector']
    src, o, u, v = g['source'], d['origin'], d['u'], d['v']
    cols, rows = d['size']
    du, dv = d['spacing']
    w = cross(u, v)
    if dot(w, sub(o, src)) <= 0:
        sys.exit('geometry: u x v points towards the source; plastimatch needs the opposite')
    nrm = scale(w, -1.0)                      # towards the source
    sid = dot(sub(src, o), nrm)               # source to detector plane
    foot = sub(src, scale(nrm, sid))          # perpendicular foot on the detector
    ic = [dot(sub(foot, o), u) / du, dot(sub(foot, o), v) / dv]
    if abs(ic[0] - (cols - 1) / 2) > 1e-6 or abs(ic[1] - (rows - 1) / 2) > 1e-6:
        sys.exit('geometry: principal point not at the detector centre; not mapped')
    sad = sid / 2
    iso = sub(src, scale(nrm, sad))
    fmt = lambda a: ' '.join('%.17g' % x for x in a)
    print('--nrm\n%s\n--vup\n%s\n--sad\n%.17g\n--sid\n%.17g\n-o\n%s\n-r\n%d %d\n-z\n%.17g %.17g'
          % (fmt(nrm), fmt(scale(v, -1.0)), sad, sid, fmt(iso), cols, rows, cols * du, rows * dv))

def compare(ours_path, pm_path, factor, volume_path, geometry_path, mode):
    dims, spacing, origin, axes, ours = read_mha(ours_path)
    w, h = dims[0], dims[1]
    pm = struct.unpack('<%df' % (w * h), open(pm_path, 'rb').read())
    vdims, vsp, vorg, vaxes, vol = read_mha(volume_path)
    g = json.load(open(geometry_path))
    d = g['detector']
    src = g['source']

    def converted(value):
        return value > -800.0 if mode == 'mu' else value != 0.0

    def to_index(p):  # continuous index of a world point (voxel centres at integers)
        r = sub(p, vorg)
        return [dot(r, vaxes[a]) / vsp[a] for a in range(3)]

    s_idx = to_index(src)
    lo, hi = [-0.5] * 3, [n - 0.5 for n in vdims]

    def interior(target):
        # Rays that cross the volume, entering and leaving through voxels that are zero after
        # conversion. Clip the ray in index space to the voxel box; look at the end voxels.
        t_idx = to_index(target)
        r = sub(t_idx, s_idx)
        t0, t1 = 0.0, 1.0
        for a in range(3):
            if abs(r[a]) < 1e-12:
                if not (lo[a] <= s_idx[a] <= hi[a]):
                    return False
                continue
            ta, tb = (lo[a] - s_idx[a]) / r[a], (hi[a] - s_idx[a]) / r[a]
            t0, t1 = max(t0, min(ta, tb)), min(t1, max(ta, tb))
        if t1 <= t0:
            return False
        eps = 1e-6 * (t1 - t0)
        for t in (t0 + eps, t1 - eps):
            p = [min(max(int(math.floor(s_idx[a] + t * r[a] + 0.5)), 0), vdims[a] - 1)
                 for a in range(3)]
            if converted(vol[p[0] + vdims[0] * (p[1] + vdims[1] * p[2])]):
                return False
        return True

    peak = max(abs(x) for x in ours) or 1.0
    stats = {'all': [0.0, 0.0, 0], 'interior': [0.0, 0.0, 0]}
    for r in range(h):
        for c in range(w):
            i = c + w * r
            diff = abs(ours[i] - factor * pm[i]) / peak
            target = add(d['origin'], add(scale(d['u'], c * d['spacing'][0]),
                                          scale(d['v'], r * d['spacing'][1])))
            for key in ('all', 'interior') if interior(target) else ('all',):
                s = stats[key]
                s[0] = max(s[0], diff)
                s[1] += diff * diff
                s[2] += 1
    out = []
    for key in ('all', 'interior'):
        mx, ss, n = stats[key]
        out.append('%.2e %.2e %d' % (mx, math.sqrt(ss / n), n) if n else '- - 0')
    print(' '.join(out))

if __name__ == '__main__':
    if sys.argv[1] == 'args':
        plastimatch_args(sys.argv[2])
    elif sys.argv[1] == 'axis-aligned':
        axis_aligned_copy(sys.argv[2], sys.argv[3])
    else:
        compare(sys.argv[2], sys.argv[3], float(sys.argv[4]), sys.argv[5], sys.argv[6],
                sys.argv[7])
PY

echo "compare_plastimatch: $(plastimatch --version 2>&1 | head -1), $THREADS thread(s), best of $REPEAT"
"$FM" convert --volume "$VOLUME" --out "$WORK/volume.mha" >/dev/null
echo "volume: $VOLUME -> $WORK/volume.mha"
OURS_VOLUME="$WORK/volume.mha"
if [ "$(python3 "$WORK/helper.py" axis-aligned "$WORK/volume.mha" "$WORK/volume_plastimatch.mha")" = oblique ]; then
    echo "volume: oblique axes; both tools render the identity-axes copy (same voxels, same grid)"
    OURS_VOLUME="$WORK/volume_plastimatch.mha"
fi

VIEWS=("AP:0,0,0,0,0,0" "lateral:0,0,0,90,0,0"
       "oblique:10,-5,20,35,25,15" "pole:0,0,0,-60,90,-30")
SIZE_OPT=()
[ -z "$SIZE" ] || SIZE_OPT=(--size "$SIZE")

printf '\n%-9s %-5s %9s %9s %7s  %-28s %-28s\n' view values "ours ms" "plm ms" ratio \
    "max/RMS rel diff, all px" "max/RMS rel diff, interior"
for view in "${VIEWS[@]}"; do
    name=${view%%:*}
    pose=${view#*:}
    "$FM" geometry --pose "$pose" --volume "$OURS_VOLUME" "${SIZE_OPT[@]}" \
        --out "$WORK/$name.json" 2>/dev/null
    mapfile -t PM_GEOMETRY < <(python3 "$WORK/helper.py" args "$WORK/$name.json")
    for values in mu raw; do
        if [ "$values" = mu ]; then
            OURS_VALUES=(--values mu --threshold -799.99997)
            PM_VALUES=(-P preprocess)
            FACTOR=$(python3 -c "print(10 * $MU_WATER / 0.022)")
        else
            OURS_VALUES=(--values raw)
            PM_VALUES=(-P none)
            FACTOR=10
        fi
        # Alternate the two tools run by run: this machine's speed swings within seconds (a
        # shared host), so each tool gets REPEAT processes spread over the same minutes and
        # its fastest render counts. Ours renders 3 times per process (the first render of a
        # process pays for cold caches and page faults; plastimatch renders once per process).
        ours_ms=""
        best=""
        for ((i = 0; i < REPEAT; i++)); do
            ms=$("$FM" drr --volume "$OURS_VOLUME" --geometry "$WORK/$name.json" \
                "${OURS_VALUES[@]}" --mode exact --threads "$THREADS" --repeat 3 \
                --out "$WORK/${name}_${values}_ours.png" --raw "$WORK/${name}_${values}_ours.mha" |
                sed -n 's/^render *\([0-9.]*\) ms.*/\1/p')
            if [ -z "$ours_ms" ] || awk -v a="$ms" -v b="$ours_ms" 'BEGIN {exit !(a < b)}'; then
                ours_ms=$ms
            fi
            log=$(OMP_NUM_THREADS=$THREADS plastimatch drr -I "$WORK/volume_plastimatch.mha" \
                -O "$WORK/${name}_${values}_plm" "${PM_GEOMETRY[@]}" "${PM_VALUES[@]}" \
                -i exact -t raw)
            # "Total time" covers the rendering and writing; subtract the writing ("I/O time").
            ms=$(echo "$log" | awk '/^Total time:/ {t = $3} /^I\/O time:/ {io = $3}
                                    END {printf "%.3f", 1000 * (t - io)}')
            if [ -z "$best" ] || awk -v a="$ms" -v b="$best" 'BEGIN {exit !(a < b)}'; then
                best=$ms
            fi
        done
        read -r amax arms _ imax irms icount < <(python3 "$WORK/helper.py" compare \
            "$WORK/${name}_${values}_ours.mha" "$WORK/${name}_${values}_plm0000.raw" \
            "$FACTOR" "$OURS_VOLUME" "$WORK/$name.json" "$values")
        ratio=$(awk -v a="$ours_ms" -v b="$best" 'BEGIN {printf "%.2f", b / a}')
        interior="$imax / $irms ($icount px)"
        [ "$icount" -gt 0 ] || interior="none (all face voxels non-zero)"
        printf '%-9s %-5s %9.2f %9.2f %6sx  %-28s %-28s\n' "$name" "$values" "$ours_ms" "$best" \
            "$ratio" "$amax / $arms" "$interior"
    done
done
echo
echo "ratio = plastimatch time / ours (render only, fastest of $REPEAT alternating runs; file loading excluded)."
echo "Differences are relative to the image's largest value, after the known unit scale."
