#!/usr/bin/env bash
# Checks view.html, the interactive 3D viewer, in a real browser: runs `lamella design` (with a
# material, so that the bending utilisation is in the page), renders its view.html in headless
# Chromium with networking disabled, and checks
#   - the page's own self-check (read back from the DOM): a WebGL context, every strip of
#     report.json drawn, strips found by the picking pass, no script or console errors; opened
#     as view.html#colour=utilisation&strip=2, the utilisation legend and strip 2's figures;
#   - a screenshot: not blank, and every strip's colour present in it;
#   - `lamella view DIR` writes view.html again from the directory's files, and that page passes
#     its self-check too.
# Reuses the build of `cargo test`; installs Debian's chromium package if missing (needs root).
set -euo pipefail
cd "$(dirname "$0")/.."

target="${CARGO_TARGET_DIR:-target}"
echo "== viewer: lamella"
# With --tests: the build `cargo test` made, nothing is rebuilt after it.
cargo build --locked --tests
lamella="$PWD/$target/debug/lamella"

if [ ! -x /usr/bin/chromium ]; then
    echo "== viewer: installing chromium"
    apt-get update -qq && apt-get install -y -qq chromium >/dev/null
fi

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
echo "== viewer: design"
"$lamella" design --out "$scratch/design" --thickness 6mm --quiet || [ $? -eq 3 ]

# Software WebGL (SwiftShader through ANGLE); no network: every host name fails to resolve and
# any proxy connection goes to a closed port.
browser=(chromium --headless --no-sandbox --user-data-dir="$scratch/profile" --use-gl=angle --use-angle=swiftshader
    --enable-unsafe-swiftshader --host-resolver-rules="MAP * ~NOTFOUND" --proxy-server=127.0.0.1:9
    --proxy-bypass-list='<-loopback>' --window-size=1280,800 --virtual-time-budget=10000 --hide-scrollbars)

# Reads the page's self-check from the DOM and compares it with report.json. With a third
# argument, the page is opened as view.html#colour=utilisation&strip=K and the legend and the
# strip panel are checked against strip K of report.json.
self_check() {
    local page="$1" report="$2" strip="${3:-}" address="file://$1"
    [ -z "$strip" ] || address="$address#colour=utilisation&strip=$strip"
    "${browser[@]}" --dump-dom "$address" 2>"$scratch/chromium.log" >"$scratch/dom.html"
    python3 - "$scratch/dom.html" "$report" "$strip" <<'PY'
import html, json, re, sys
dom = open(sys.argv[1], encoding="utf-8").read()
match = re.search(r'<pre id="lamella-self-check"[^>]*>(.*?)</pre>', dom, re.S)
if not match:
    sys.exit("no self-check in the page")
check = json.loads(html.unescape(match.group(1)))
expected = json.load(open(sys.argv[2]))["strips"]["overall"]["strip_count"]
print("self-check:", {k: v for k, v in check.items() if k not in ("colours", "legend", "info")})
problems = []
if not check["webgl"]:
    problems.append("no WebGL context")
if check["errors"]:
    problems.append("script errors: %s" % check["errors"])
if not (check["strips_expected"] == check["strips_drawn"] == expected):
    problems.append("%d strips in report.json, %d in the page, %d drawn" % (expected, check["strips_expected"], check["strips_drawn"]))
if check["strips_seen"] < 1:
    problems.append("no strip visible in the 3D view")
if sys.argv[3]:
    strip = json.load(open(sys.argv[2]))["strips"]["strips"][int(sys.argv[3])]
    figures = "%s (id %s" % (strip["name"], strip["id"]), "%.3f m" % strip["length_m"], "%.3f °" % strip["max_diff_theta_degrees"]
    if check["colouring"] != "utilisation" or "utilisation" not in check["legend"] or " %" not in check["legend"]:
        problems.append("colouring %s with the legend '%s'" % (check["colouring"], check["legend"]))
    problems += ["the strip panel '%s' lacks '%s'" % (check["info"], f) for f in figures if f not in check["info"]]
if problems:
    sys.exit("self-check failed: " + "; ".join(problems))
json.dump(check["colours"], open(sys.argv[1] + ".colours.json", "w"))
PY
}

echo "== viewer: self-check of design's view.html"
self_check "$scratch/design/view.html" "$scratch/design/report.json"
cp "$scratch/dom.html.colours.json" "$scratch/colours.json"

echo "== viewer: colour by utilisation, strip 2 selected"
self_check "$scratch/design/view.html" "$scratch/design/report.json" 2

echo "== viewer: screenshot"
"${browser[@]}" --screenshot="$scratch/view.png" "file://$scratch/design/view.html" 2>"$scratch/chromium.log" >/dev/null
python3 - "$scratch/view.png" "$scratch/colours.json" <<'PY'
import json, struct, sys, zlib

def read_png(path):
    """8-bit RGB or RGBA, non-interlaced PNG as rows of (r, g, b) tuples."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit("not a PNG")
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    if depth != 8 or colour not in (2, 6) or interlace:
        sys.exit("unexpected PNG format: depth %d, colour type %d, interlace %d" % (depth, colour, interlace))
    channels = 3 if colour == 2 else 4
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up, corner = previous[i], previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows

width, height, rows = read_png(sys.argv[1])
counts = {}
for row in rows:
    for pixel in row:
        counts[pixel] = counts.get(pixel, 0) + 1
background = max(counts.values())
print("screenshot: %dx%d, %d colours, %.0f %% in the most common one" % (width, height, len(counts), 100.0 * background / (width * height)))
if len(counts) < 100 or background > 0.9 * width * height:
    sys.exit("the screenshot is blank")
colours = [tuple(int(c[k:k + 2], 16) for k in (1, 3, 5)) for c in json.load(open(sys.argv[2]))]
missing = []
for colour in colours:
    found = sum(n for pixel, n in counts.items() if all(abs(pixel[k] - colour[k]) <= 6 for k in range(3)))
    if found < 20:
        missing.append("#%02x%02x%02x (%d pixels)" % (colour + (found,)))
print("screenshot: %d of %d strip colours present" % (len(colours) - len(missing), len(colours)))
if missing:
    sys.exit("strip colours missing from the screenshot: " + ", ".join(missing))
PY

echo "== viewer: lamella view DIR"
rm "$scratch/design/view.html"
printed="$("$lamella" view "$scratch/design")"
[ "$printed" = "$scratch/design/view.html" ] || { echo "lamella view printed '$printed'"; exit 1; }
self_check "$scratch/design/view.html" "$scratch/design/report.json"
# The directory is still a Lamella output that --force may replace.
"$lamella" strips --field "$scratch/design/field.csv" --strips 4 --out "$scratch/design" --force --quiet || [ $? -eq 3 ]
echo "== viewer: all checks passed"
