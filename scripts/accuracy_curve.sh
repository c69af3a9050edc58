#!/usr/bin/env bash
# The accuracy against photon count as a curve: reads the table scripts/simulate_accuracy.sh
# prints (markdown) and writes an SVG of the worst centre error (mm) and the worst rotation error
# (deg) of each photon count, photons on a log axis (the noiseless row drawn at the right, as the
# limit), the 0.5 mm / 0.5 deg bound dashed.
#   bash scripts/accuracy_curve.sh TABLE.md OUT.svg [TITLE]
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 TABLE.md OUT.svg [TITLE]" >&2; exit 2; }
TABLE=$1 OUT=$2 TITLE=${3:-Tracking accuracy against photon count}
[ -r "$TABLE" ] || { echo "$TABLE: cannot read" >&2; exit 1; }
tmp=$(mktemp "$OUT.XXXXXX")
trap 'rm -f "$tmp"' EXIT
awk -F'|' -v title="$TITLE" '
function trim(s) { gsub(/^ +| +$/, "", s); return s }
# rows: | photons | centre RMS | centre worst | rotation RMS | rotation worst | within | s/frame |
NF >= 8 && trim($2) ~ /^([0-9]+|no noise)$/ {
    p = trim($2); n++
    photons[n] = (p == "no noise") ? -1 : p + 0
    centre[n] = trim($4) + 0; rotation[n] = trim($6) + 0
    if (photons[n] > 0) { lp = log(photons[n]) / log(10); if (!set || lp < lo) lo = lp; if (!set || lp > hi) hi = lp; set = 1 }
    if (centre[n] > ymax) ymax = centre[n]; if (rotation[n] > ymax) ymax = rotation[n]
}
END {
    if (n == 0) { print "no rows of photon counts in the table" > "/dev/stderr"; exit 1 }
    if (!set) { lo = 2; hi = 5 }
    lo = int(lo); hi = int(hi + 0.999); if (hi <= lo) hi = lo + 1
    top = ymax < 0.6 ? 0.6 : ymax * 1.1                 # the bound always in view
    W = 640; H = 400; L = 70; R = 110; T = 40; B = 60    # plot area inside the margins
    pw = W - L - R; ph = H - T - B
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"12\">\n", W, H
    printf "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", W, H
    printf "<text x=\"%d\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">%s</text>\n", W / 2, title
    printf "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"black\"/>\n", L, T, pw, ph
    # x: decades of photons, the noiseless limit one step right of the last decade
    span = hi - lo + 1
    for (d = lo; d <= hi; d++) {
        x = L + (d - lo) / span * pw
        printf "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#ddd\"/>\n", x, T, x, T + ph
        printf "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">1e%d</text>\n", x, T + ph + 18, d
    }
    xn = L + pw
    printf "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">no noise</text>\n", xn, T + ph + 18
    printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">photons per pixel at the anatomy'"'"'s median</text>\n", L + pw / 2, H - 12
    for (k = 0; k <= 5; k++) {
        v = top * k / 5; y = T + ph - v / top * ph
        printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#eee\"/>\n", L, y, L + pw, y
        printf "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%.2f</text>\n", L - 6, y + 4, v
    }
    printf "<text x=\"18\" y=\"%d\" transform=\"rotate(-90 18 %d)\" text-anchor=\"middle\">worst error (mm, deg)</text>\n", T + ph / 2, T + ph / 2
    yb = T + ph - 0.5 / top * ph
    printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#c00\" stroke-dasharray=\"6 4\"/>\n", L, yb, L + pw, yb
    printf "<text x=\"%d\" y=\"%.1f\" fill=\"#c00\">0.5 mm / 0.5 deg</text>\n", L + pw + 6, yb + 4
    split("centre rotation", names, " "); split("#1f5fa8 #d07000", colours, " ")
    for (s = 1; s <= 2; s++) {
        pts = ""
        for (i = 1; i <= n; i++) {
            x = photons[i] < 0 ? xn : L + (log(photons[i]) / log(10) - lo) / span * pw
            v = s == 1 ? centre[i] : rotation[i]
            y = T + ph - v / top * ph
            key[i] = x; val[i] = y
        }
        # drawn in order of x (the table lists the noiseless row first)
        for (i = 1; i <= n; i++) order[i] = i
        for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (key[order[j]] < key[order[i]]) { t = order[i]; order[i] = order[j]; order[j] = t }
        for (i = 1; i <= n; i++) pts = pts sprintf("%.1f,%.1f ", key[order[i]], val[order[i]])
        printf "<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"2\"/>\n", pts, colours[s]
        for (i = 1; i <= n; i++) printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"%s\"/>\n", key[i], val[i], colours[s]
        printf "<text x=\"%d\" y=\"%d\" fill=\"%s\">%s</text>\n", L + pw + 6, T + 14 + 16 * s, colours[s], s == 1 ? "centre, mm" : "rotation, deg"
    }
    print "</svg>"
}' "$TABLE" > "$tmp"
mv "$tmp" "$OUT"
trap - EXIT
echo "$OUT written"
