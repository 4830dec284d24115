"""Runs the documented ParaView snippets (Examples/paraview/) exactly as
docs/paraview.md gives them, on a volume whose point array has an unusual name, and
checks that the volume shows. Plain python3 (no numpy: the system Python has none);
ParaView runs as a child process through scripts/paraview-env.sh, as documented.

  python3 snippet_test.py pvbatch --out-dir D [--snippet FILE]   # render_volume_pvbatch.py
  python3 snippet_test.py gui-pvbatch --out-dir D    # show_volume_gui.py, in pvbatch
  python3 snippet_test.py gui --out-dir D            # show_volume_gui.py, paraview --script
  python3 snippet_test.py docs                       # the doc quotes the files verbatim

Environment: PV_BUILD_DIR, the plugin's build folder (CTest sets it). Each case ends
with "<case>: passed" or lines starting with "FAILED".
"""
import argparse
import os
import re
import struct
import subprocess
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
PVBATCH_SNIPPET = os.path.join(ROOT, "Examples", "paraview", "render_volume_pvbatch.py")
GUI_SNIPPET = os.path.join(ROOT, "Examples", "paraview", "show_volume_gui.py")
GUI_DRIVER = os.path.join(HERE, "gui_script_driver.py")
ENV_SCRIPT = os.path.join(ROOT, "scripts", "paraview-env.sh")
DOC = os.path.join(ROOT, "docs", "paraview.md")
# Not "ImageFile" or "scalars": the old snippet coloured by a hard-coded "ImageFile"
# and rendered nothing on a .vti.
ARRAY_NAME = "density_g-cc_2"
# The volume covers about a third of the image; at least this fraction of the pixels
# must differ from the background, with at least this mean brightness there.
MIN_VOLUME_FRACTION = 0.02
MIN_VOLUME_MEAN = 40.0

failures = []


def check(ok, what):
    print(("ok:     " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


def write_vti(path, n=40):
    """A ball of bone-like values (200) in a soft shell (100) in air (0), uint8, with
    the point array named ARRAY_NAME; ASCII VTK XML, no library needed."""
    values = []
    c = (n - 1) / 2.0
    for z in range(n):
        for y in range(n):
            for x in range(n):
                r = ((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2) ** 0.5
                values.append(200 if r < 0.25 * n else 100 if r < 0.4 * n else 0)
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="ImageData" version="0.1">\n')
        f.write('<ImageData WholeExtent="0 %d 0 %d 0 %d" Origin="0 0 0" Spacing="1 1 1">\n'
                % (n - 1, n - 1, n - 1))
        f.write('<Piece Extent="0 %d 0 %d 0 %d">\n<PointData Scalars="%s">\n'
                % (n - 1, n - 1, n - 1, ARRAY_NAME))
        f.write('<DataArray type="UInt8" Name="%s" format="ascii">\n' % ARRAY_NAME)
        for i in range(0, len(values), 40):
            f.write(" ".join(str(v) for v in values[i:i + 40]) + "\n")
        f.write("</DataArray>\n</PointData>\n<CellData/>\n</Piece>\n</ImageData>\n</VTKFile>\n")


def read_png(path):
    """(width, height, channels, rows of bytes) of an 8-bit RGB/RGBA PNG."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("%s is not a PNG" % path)
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
    width, height, depth, color, _, _, interlace = header
    if depth != 8 or color not in (2, 6) or interlace:
        raise ValueError("%s: only 8-bit RGB/RGBA PNG without interlace" % path)
    channels = 3 if color == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        row = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = row[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(row)
        previous = row
    return width, height, channels, rows


def check_image_shows_volume(png):
    """The volume must cover part of the image, and not as black."""
    if not os.path.isfile(png):
        check(False, "%s was written" % png)
        return
    width, height, channels, rows = read_png(png)
    background = tuple(rows[0][0:3])
    volume, brightness = 0, 0.0
    for row in rows:
        for x in range(width):
            rgb = row[x * channels:x * channels + 3]
            if max(abs(rgb[c] - background[c]) for c in range(3)) > 16:
                volume += 1
                brightness += sum(rgb) / 3.0
    fraction = volume / float(width * height)
    mean = brightness / volume if volume else 0.0
    check(fraction >= MIN_VOLUME_FRACTION,
          "the volume covers %.1f %% of the image (background %s; at least %.0f %%)"
          % (100 * fraction, background, 100 * MIN_VOLUME_FRACTION))
    check(mean >= MIN_VOLUME_MEAN, "the volume's pixels have a mean brightness of %.1f "
          "(at least %.0f: not black)" % (mean, MIN_VOLUME_MEAN))


def run(command, env=None, timeout=180):
    print("running: " + " ".join(command))
    sys.stdout.flush()
    try:
        result = subprocess.run(command, env=env, timeout=timeout, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, universal_newlines=True)
    except subprocess.TimeoutExpired as e:
        # The GUI stays open after a failed --script (e.g. "No module named 'paraview'").
        print(e.output or "")
        return subprocess.CompletedProcess(command, -1, "timed out after %d s" % timeout)
    print(result.stdout)
    return result


def case_pvbatch(args):
    vti = os.path.join(args.out_dir, "odd-array-name.vti")
    png = os.path.join(args.out_dir, "snippet-pvbatch.png")
    write_vti(vti)
    if os.path.exists(png):
        os.remove(png)
    result = run(["bash", ENV_SCRIPT, "pvbatch", args.snippet, vti, png])
    check(result.returncode == 0, "pvbatch exited with %d" % result.returncode)
    check("Could not determine array range" not in result.stdout,
          "no 'Could not determine array range' warning")
    check_image_shows_volume(png)


def case_gui(args, executable):
    vti = os.path.join(args.out_dir, "odd-array-name.vti")
    png = os.path.join(args.out_dir, "snippet-gui-%s.png" % executable)
    write_vti(vti)
    for stale in (png, png + ".done"):
        if os.path.exists(stale):
            os.remove(stale)
    env = dict(os.environ, SCATTERER_VOLUME=vti, SCATTERER_SNIPPET=GUI_SNIPPET,
               SCATTERER_PNG=png)
    if executable == "paraview":
        # The GUI's own --script, through the launcher; the driver exits the GUI.
        command = ["bash", ENV_SCRIPT, "paraview", "--dr", "--script=" + GUI_DRIVER]
    else:
        command = ["bash", ENV_SCRIPT, "pvbatch", GUI_DRIVER]
    result = run(command, env=env, timeout=90)
    check(result.returncode == 0, "%s exited with %d" % (executable, result.returncode))
    check(os.path.isfile(png + ".done"), "the snippet ran to its end")
    check_image_shows_volume(png)


def python_blocks(text):
    return re.findall(r"```python\n(.*?)```", text, re.S)


def case_docs(args):
    with open(DOC) as f:
        blocks = python_blocks(f.read())
    for path in (PVBATCH_SNIPPET, GUI_SNIPPET):
        with open(path) as f:
            code = f.read()
        check(code in blocks, "docs/paraview.md quotes %s verbatim in a ```python block"
              % os.path.relpath(path, ROOT))


parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("case", choices=["pvbatch", "gui-pvbatch", "gui", "docs"])
parser.add_argument("--out-dir", default=".")
parser.add_argument("--snippet", default=PVBATCH_SNIPPET)
args = parser.parse_args()
os.makedirs(args.out_dir, exist_ok=True)
if args.case == "pvbatch":
    case_pvbatch(args)
elif args.case == "gui-pvbatch":
    case_gui(args, "pvbatch")
elif args.case == "gui":
    case_gui(args, "paraview")
else:
    case_docs(args)
print("%s: %s" % (args.case, "FAILED (%d)" % len(failures) if failures else "passed"))
sys.exit(1 if failures else 0)
