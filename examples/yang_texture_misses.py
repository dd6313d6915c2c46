"""Yang, Mitra and Huang (2004), "Improving Rendering by Texture Map-Based Triangle Strips":
texture-cache misses against cache size for triangle strips and their texture-grouped order
(Figure 9: the bunny with the four-colour texture), end to end from Python.

Each order renders the bunny once (back faces culled, trilinear filtering, a FIFO-16 vertex
cache) and writes its texel trace; a sweep replays the trace through fully associative LRU
texture caches of 1 KiB to 64 KiB with 64-byte lines; the figure plots the miss rate against
the cache size, one line per order. `rastrace texsweep --experiment fig9` computes the same rows.

    python3 examples/yang_texture_misses.py -o out/yang   # writes out/yang/yang-fig9.png, .csv
"""

import argparse
import pathlib
import tempfile

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt
import pandas as pd

import rastrace

ORDERS = ("strip", "texgroup")
CACHES = "size=1KiB..64KiB,line=64B,assoc=full,policy=lru,layout=linear"


def texture_misses(scene, size):
    """One row per order and cache size: the order's sweep over its own frame's texel trace."""
    frames = []
    with tempfile.TemporaryDirectory() as folder:
        for order in ORDERS:
            trace = pathlib.Path(folder) / f"{order}.rtrace"
            frame = rastrace.render(scene, trace=str(trace), order=order, cull="back", size=size)
            sweep = pd.DataFrame(rastrace.sweep(str(trace), CACHES))
            sweep.insert(0, "order", order)
            sweep["vertex_acmr"] = frame["acmr"][0]
            frames.append(sweep)
    return pd.concat(frames, ignore_index=True)


def plot(rows, path):
    figure, axes = plt.subplots(figsize=(6, 4))
    for order, group in rows.groupby("order", sort=False):
        axes.plot(group["size_bytes"] / 1024, group["miss_rate"], marker="o", label=order)
    axes.set_xscale("log", base=2)
    axes.set_xlabel("texture cache size (KiB), fully associative LRU, 64-byte lines")
    axes.set_ylabel("texture miss rate")
    axes.set_title("Texture-grouped order against strips (Yang et al., Figure 9)")
    axes.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-o", "--output", default="out/yang", help="folder for the plot and the table")
    parser.add_argument("--scene", default="builtin:bunny")
    parser.add_argument("--size", default="", help="image size WxH (default: the scene's)")
    args = parser.parse_args()
    output = pathlib.Path(args.output)
    output.mkdir(parents=True, exist_ok=True)
    rows = texture_misses(args.scene, args.size)
    rows.to_csv(output / "yang-fig9.csv", index=False)
    plot(rows, output / "yang-fig9.png")
    print(rows[["order", "size_bytes", "misses", "miss_rate", "vertex_acmr"]].to_string(index=False))


if __name__ == "__main__":
    main()
