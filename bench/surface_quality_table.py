#!/usr/bin/env python3
"""The quality table of bench/surface_synthesis.sh: one row per mesh x exemplar pair.

Reads what the bench wrote under OUTPUT_DIR (quality/surface.tsv, quality/solids.tsv,
quality/image.tsv, analyses.tsv), writes OUTPUT_DIR/quality.tsv (every column, one row per pair)
and prints the markdown section on stdout, ending with the summary line: how many pairs pass each
target and the worst pair per measure. A measure eval does not report reads "n/a" and counts as
neither pass nor fail.

Usage: bench/surface_quality_table.py OUTPUT_DIR [--vertices N] [--seed N] [--threads N]
       [--samples N] [--image-size N] [--solids METHOD...]
"""
import argparse
import csv
import math
import os

# The targets: surface flatness at most FLATNESS; histogram and coherence at most these multiples of
# 2D optimize's on the same exemplar (coherence: 2D's image copied onto a retiled plane).
FLATNESS = 0.05
HISTOGRAM_RATIO = 1.5
COHERENCE_RATIO = 1.3


def number(text):
    """A float, or None for "n/a", an empty cell or anything else that is not a finite number."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def cell(value, digits=3, suffix=""):
    return "n/a" if value is None else f"{value:.{digits}f}{suffix}"


def ratio(a, b):
    return None if a is None or b is None or b <= 0 else a / b


def verdict(value, limit):
    return "n/a" if value is None else "yes" if value <= limit else "no"


def read(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f, delimiter="\t"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--vertices", type=int, default=48000)
    parser.add_argument("--seed", default="3")
    parser.add_argument("--threads", default="2")
    parser.add_argument("--samples", default="4000")
    parser.add_argument("--image-size", default="256")
    parser.add_argument("--solids", nargs="*", default=["tile-blend"])
    args = parser.parse_args()
    out = args.out

    surface = read(f"{out}/quality/surface.tsv")
    solids = {(r["mesh"], r["exemplar"], r["method"]): r for r in read(f"{out}/quality/solids.tsv")}
    images = {r["exemplar"]: r for r in read(f"{out}/quality/image.tsv")}
    floors = {r["exemplar"]: r for r in read(f"{out}/analyses.tsv")}
    measures = ("coherence", "rotation_invariant", "completeness", "histogram", "flatness")

    rows = []
    for s in surface:
        key = (s["mesh"], s["exemplar"])
        image = images.get(s["exemplar"], {})
        row = {"mesh": s["mesh"], "exemplar": s["exemplar"], "size": s["size"], "vertices": s["vertices"],
               "seconds": number(s["seconds"])}
        row.update({m: number(s.get(m)) for m in measures})
        for method in args.solids:
            solid = solids.get(key + (method,), {})
            row.update({f"{method}_{m}": number(solid.get(m)) for m in measures})
        row["image_coherence"] = number(image.get("coherence"))
        row["image_histogram"] = number(image.get("histogram"))
        row["histogram_ratio"] = ratio(row["histogram"], row["image_histogram"])
        row["coherence_ratio"] = ratio(row["coherence"], row["image_coherence"])
        row["image_plane_coherence"] = number(image.get("plane_coherence"))
        row["plane_coherence_ratio"] = ratio(row["coherence"], row["image_plane_coherence"])
        row["flatness_pass"] = verdict(row["flatness"], FLATNESS)
        row["histogram_pass"] = verdict(row["histogram_ratio"], HISTOGRAM_RATIO)
        row["coherence_pass"] = verdict(row["coherence_ratio"], COHERENCE_RATIO)
        row["plane_coherence_pass"] = verdict(row["plane_coherence_ratio"], COHERENCE_RATIO)
        passes = [row["flatness_pass"], row["histogram_pass"], row["plane_coherence_pass"]]
        row["pass"] = "no" if "no" in passes else "n/a" if "n/a" in passes else "yes"
        row["render"] = s.get("render", "")
        rows.append(row)

    # quality.tsv: every column.
    columns = ["mesh", "exemplar", "size", "vertices", "seconds", *measures,
               *(f"{method}_{m}" for method in args.solids for m in measures),
               "image_coherence", "image_histogram", "histogram_ratio", "coherence_ratio",
               "image_plane_coherence", "plane_coherence_ratio",
               "flatness_pass", "histogram_pass", "coherence_pass", "plane_coherence_pass", "pass", "render"]
    with open(f"{out}/quality.tsv", "w") as f:
        f.write("\t".join(columns) + "\n")
        for row in rows:
            f.write("\t".join(
                cell(row[c], 2 if c == "seconds" else 3) if isinstance(row[c], float) or row[c] is None
                else str(row[c]) for c in columns) + "\n")

    k = args.vertices // 1000
    print(f"\n## Quality at {k}K vertices\n")
    solid_names = " and ".join(args.solids) if args.solids else "no"
    print(f"Every mesh x exemplar pair at the surface command's defaults (`--vertices {args.vertices} --seed "
          f"{args.seed} --threads {args.threads}`). Surface measures from `texsynth eval EXEMPLAR colored.ply --json` "
          f"({args.samples} sampled vertices, 7x7 patches, colors 0..255): coherence (output patches to their nearest "
          "exemplar patch: lower = no invented content), completeness (exemplar patches to the output: lower = "
          "nothing of the exemplar missing), histogram distance of the colors, flatness (how much of the surface "
          "turned flat); n/a where this eval does not report the measure. Seconds: the synthesis (coarse-to-fine "
          f"optimization) from --stats. {solid_names} solid: colored onto the very same retiled vertices, coherence "
          f"/ histogram / flatness. 2D: image coherence / histogram of `texsynth image --method optimize --tileable "
          f"never --size {args.image_size}` on the same exemplar. Ratios: surface over 2D. 2D coherence is read "
          "two ways: as an image (pixel-aligned patches), and on the surface's footing: the same 2D image copied "
          "pixel by pixel onto a flat plane retiled at one pixel per vertex spacing and measured as a surface, "
          "so that both pay the resampling between irregular vertices (the exemplar itself copied that way, the "
          "floor, already reads 1.1-3.6x 2D's image coherence). Pass: flatness <= "
          f"{FLATNESS}, histogram <= {HISTOGRAM_RATIO}x 2D's, coherence <= {COHERENCE_RATIO}x 2D's on the surface's "
          "footing (yes; or the targets missed; n/a when a measure is missing and the others pass); the image "
          "coherence ratio is shown beside it.\n")
    solid_heads = "".join(f" {method} |" for method in args.solids)
    print(f"| mesh | exemplar | seconds | coherence | completeness | histogram | flatness |{solid_heads} 2D | "
          "histogram ratio | coherence ratio (image) | coherence ratio (plane) | pass | render |")
    print("|---|---|---:|---:|---:|---:|---:|" + "---:|" * len(args.solids) + "---:|---:|---:|---:|---|---|")
    for row in rows:
        solid_cells = "".join(
            f" {cell(row[f'{m}_coherence'])} / {cell(row[f'{m}_histogram'])} / {cell(row[f'{m}_flatness'])} |"
            for m in args.solids)
        missed = [name for name in ("flatness", "histogram", "plane_coherence") if row[f"{name}_pass"] == "no"]
        verdict_cell = f"no: {', '.join(missed)}" if missed else row["pass"]
        render = f"[png]({row['render']})" if row["render"] else ""
        print(f"| {row['mesh']} | {row['exemplar']} ({row['size']}) | {cell(row['seconds'], 2)} | "
              f"{cell(row['coherence'])} | {cell(row['completeness'])} | {cell(row['histogram'])} | "
              f"{cell(row['flatness'])} |{solid_cells} {cell(row['image_coherence'])} / "
              f"{cell(row['image_histogram'])} (plane {cell(row['image_plane_coherence'])}) | "
              f"{cell(row['histogram_ratio'], 2, 'x')} | {cell(row['coherence_ratio'], 2, 'x')} | "
              f"{cell(row['plane_coherence_ratio'], 2, 'x')} | {verdict_cell.replace('plane_coherence', 'coherence')} | "
              f"{render} |")

    if images:
        print(f"\n2D optimize at {args.image_size}², once per exemplar, and the floor (the exemplar copied onto a "
              "flat retiled plane, surface coherence):\n")
        print("| exemplar | size | coherence | completeness | histogram | flatness | seconds | coherence on a plane | floor |")
        print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
        for name, image in images.items():
            print(f"| {name} | {image['size']} | {cell(number(image['coherence']))} | "
                  f"{cell(number(image['completeness']))} | {cell(number(image['histogram']))} | "
                  f"{cell(number(image['flatness']))} | {image['seconds']} s | "
                  f"{cell(number(image.get('plane_coherence')))} | "
                  f"{floors.get(name, {}).get('floor_coherence', '')} |")
    if os.path.exists(f"{out}/renders/sheet.png"):
        print("\nRenders: renders/MESH_EXEMPLAR.png, all of them in [renders/sheet.png](renders/sheet.png) "
              "(a row per exemplar, a column per mesh).")

    # The summary line, last.
    n = len(rows)
    if n == 0:
        print("\nSummary: no quality pairs.")
        return

    def count(name):
        verdicts = [row[f"{name}_pass"] for row in rows]
        unknown = verdicts.count("n/a")
        return f"{verdicts.count('yes')}/{n}" + (f" ({unknown} n/a)" if unknown else "")

    def worst(key, digits=3, suffix=""):
        known = [row for row in rows if row[key] is not None]
        if not known:
            return "n/a"
        row = max(known, key=lambda r: r[key])
        return f"{cell(row[key], digits, suffix)} ({row['mesh']} {row['exemplar']})"

    all_three = sum(row["pass"] == "yes" for row in rows)
    below_solid = ""
    if args.solids:
        method = args.solids[0]
        known = [row for row in rows if row["coherence"] is not None and row[f"{method}_coherence"] is not None]
        below = sum(row["coherence"] < row[f"{method}_coherence"] for row in known)
        below_solid = f"; surface coherence below {method}'s: {below}/{len(known)}"
    print(f"\nSummary ({n} pair{'s' * (n != 1)}): flatness <= {FLATNESS}: {count('flatness')}; histogram <= {HISTOGRAM_RATIO}x 2D: "
          f"{count('histogram')}; coherence <= {COHERENCE_RATIO}x 2D on the surface's footing: "
          f"{count('plane_coherence')} (as images: {count('coherence')}); all three: {all_three}/{n}"
          f"{below_solid}. Worst: flatness {worst('flatness')}, histogram {worst('histogram_ratio', 2, 'x 2D')}, "
          f"coherence {worst('plane_coherence_ratio', 2, 'x 2D on a plane')}, completeness {worst('completeness')}, "
          f"synthesis {worst('seconds', 2, ' s')}.")


if __name__ == "__main__":
    main()
