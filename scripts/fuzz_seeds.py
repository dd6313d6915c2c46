#!/usr/bin/env python3
"""Generates the bigger fuzz seeds (scripts/fuzz.sh) from the real data and rendered traces.

Usage: scripts/fuzz_seeds.py OUT [RASTRACE]
Writes OUT/<target>/<name> for the targets of fuzz/: the CGAL meshes and assimp's test models
(data/, scripts/setup.sh) small enough for the target's -max_len, and traces rendered by RASTRACE
(default build/apps/rastrace; traces are skipped with a note when it is missing) with their CSV
export, a din file of their texel addresses, and their chunks in the trace_chunk target's format
(u8 kind | u8 flags | u32 records | the encoded records). The small seeds in fuzz/corpus/ are
committed; these are not (they are made from files git does not hold).
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DATA = Path(os.environ.get("RASTRACE_DATA", ROOT / "data"))
TEXT_MAX = 16384   # scripts/fuzz.sh -max_len for text formats
BINARY_MAX = 65536  # and for binary ones
# fuzz/assimp.cpp: the first byte picks the extension, in this order.
ASSIMP_EXTENSIONS = [".gltf", ".glb", ".dae", ".3ds", ".ase", ".stl", ".x", ".ac", ".md2", ".lwo", ".ms3d", ".3mf"]


def put(out, target, name, data):
    folder = out / target
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data)


def small_files(folder, pattern, limit):
    return sorted(p for p in folder.rglob(pattern) if p.is_file() and p.stat().st_size <= limit)


def mesh_seeds(out):
    for p in small_files(DATA / "meshes", "*.off", TEXT_MAX):
        put(out, "off", p.stem, p.read_bytes())
    for p in small_files(DATA / "meshes", "*.ply", BINARY_MAX):
        put(out, "ply", p.stem, p.read_bytes())
    # OBJ with its MTL appended after the separator fuzz/obj.cpp splits at.
    for p in small_files(DATA / "assimp", "*.obj", TEXT_MAX):
        lines, mtl = [], b""
        for line in p.read_bytes().splitlines(keepends=True):
            if line.strip().startswith(b"mtllib"):
                library = p.parent / line.split(None, 1)[1].strip().decode("latin-1")
                if library.is_file() and library.stat().st_size <= TEXT_MAX:
                    mtl = b"\n".join(
                        b"map_Kd t.png" if l.strip().startswith(b"map_Kd") else l
                        for l in library.read_bytes().splitlines())
                line = b"mtllib m.mtl\n"
            lines.append(line)
        body = b"".join(lines) + (b"\n%%MTL%%\n" + mtl if mtl else b"")
        if len(body) <= TEXT_MAX:
            put(out, "obj", p.parent.name + "_" + p.stem, body)
    for p in small_files(DATA / "assimp", "*", BINARY_MAX - 1):
        ext = p.suffix.lower()
        # AC3D's "subdiv N" makes assimp subdivide N times (4^N faces): sample_subdiv.ac's
        # "subdiv 6" takes 1.3 s in Release and over the 5 s limit under ASan. Slow by request,
        # not a parser fault (docs/RELIABILITY.md): not a seed.
        if ext == ".ac" and b"subdiv" in p.read_bytes():
            continue
        if ext in ASSIMP_EXTENSIONS:
            tag = bytes([ASSIMP_EXTENSIONS.index(ext)])
            put(out, "assimp", p.parent.name + "_" + p.name, tag + p.read_bytes())
    for p in sorted((ROOT / "docs").glob("*.json")) + sorted((ROOT / "examples").rglob("*.json")):
        if p.stat().st_size <= TEXT_MAX:
            put(out, "scene", p.stem, p.read_bytes())


def chunks(trace):
    """(kind, flags, records, payload) of every chunk, read through the footer's index."""
    index_offset = struct.unpack_from("<Q", trace, len(trace) - 24)[0]
    count = struct.unpack_from("<Q", trace, index_offset + 8)[0]
    for i in range(count):
        offset = struct.unpack_from("<Q", trace, index_offset + 16 + 24 * i)[0]
        _, kind, flags, _, records, stored, _, _, _ = struct.unpack_from("<IBBHIIIQI", trace, offset)
        yield kind, flags, records, trace[offset + 32:offset + 32 + stored]


def trace_seeds(out, rastrace):
    renders = [  # small frames: every chunk kind, lists and strips, a version 1 file, two frames
        ["builtin:grid", "--size", "32x24"],
        ["builtin:grid", "--size", "24x16", "--order", "tipsy"],
        ["builtin:grid", "--size", "16x16", "--raster", "tiled8", "--order", "strip"],
        ["builtin:grid", "--size", "16x12", "--frames", "2"],  # several frames: frame numbers
    ]
    with tempfile.TemporaryDirectory() as tmp:
        traces = [ROOT / "tests" / "traces" / "data" / "v1_grid_16x12.rtrace"]
        for i, args in enumerate(renders):
            path = Path(tmp) / f"render{i}.rtrace"
            result = subprocess.run([rastrace, "render", *args, "-o", str(Path(tmp) / "f.png"), "--trace", str(path)],
                                    capture_output=True, text=True)
            if result.returncode == 0:
                traces.append(path)
            else:
                print(f"fuzz_seeds: render {' '.join(args)} failed: {result.stderr.strip()}", file=sys.stderr)
        for path in traces:
            data = path.read_bytes()
            if len(data) <= BINARY_MAX:
                put(out, "trace_reader", path.stem, data)
            for n, (kind, flags, records, payload) in enumerate(chunks(data)):
                raw = subprocess.run(["zstd", "-d", "-c", "-q"], input=payload, capture_output=True, check=True).stdout
                if len(raw) + 6 <= BINARY_MAX and n < 16:
                    put(out, "trace_chunk", f"{path.stem}_{n}", bytes([kind - 1, flags]) + struct.pack("<I", records) + raw)
            csv = Path(tmp) / (path.stem + ".csv")
            if subprocess.run([rastrace, "trace", "convert", str(path), str(csv)], capture_output=True).returncode:
                continue
            lines = csv.read_bytes().splitlines(keepends=True)
            # The metadata and header lines, then up to 40 events of each kind, in file order.
            kept, seen = lines[:2], {}
            for line in lines[2:]:
                event = line.split(b",", 1)[0]
                seen[event] = seen.get(event, 0) + 1
                if seen[event] <= 40:
                    kept.append(line)
            put(out, "csv_trace", path.stem, b"".join(kept)[:TEXT_MAX])
            # A din file of the texel accesses (row-major, 4-byte texels, levels 16 MiB apart).
            din = []
            for line in lines[2:]:
                f = line.decode().rstrip("\n").split(",")
                if f[0] == "texel":
                    address = (int(f[6]) << 28) + (int(f[7]) << 24) + (int(f[9]) * 4096 + int(f[8])) * 4
                    din.append(f"0 {address:x}\n")
                if len(din) == 400:
                    break
            if din:
                put(out, "din", path.stem, "".join(din).encode())
                # The same accesses as a trace of address chunks (the fourth record kind).
                din_path, address_trace = Path(tmp) / "a.din", Path(tmp) / (path.stem + "_din.rtrace")
                din_path.write_text("".join(din))
                if not subprocess.run([rastrace, "trace", "convert", str(din_path), str(address_trace)],
                                      capture_output=True).returncode:
                    data = address_trace.read_bytes()
                    put(out, "trace_reader", address_trace.stem, data)
                    for n, (kind, flags, records, payload) in enumerate(chunks(data)):
                        raw = subprocess.run(["zstd", "-d", "-c", "-q"], input=payload, capture_output=True,
                                             check=True).stdout
                        put(out, "trace_chunk", f"{address_trace.stem}_{n}",
                            bytes([kind - 1, flags]) + struct.pack("<I", records) + raw)


def main():
    out = Path(sys.argv[1])
    rastrace = sys.argv[2] if len(sys.argv) > 2 else str(ROOT / "build" / "apps" / "rastrace")
    shutil.rmtree(out, ignore_errors=True)
    mesh_seeds(out)
    if Path(rastrace).is_file():
        trace_seeds(out, rastrace)
    else:
        print(f"fuzz_seeds: {rastrace} not built: no trace seeds beyond the committed ones", file=sys.stderr)
    counts = {t.name: len(list(t.iterdir())) for t in sorted(out.iterdir())}
    print("fuzz_seeds: " + ", ".join(f"{k} {v}" for k, v in counts.items()), file=sys.stderr)


if __name__ == "__main__":
    main()
