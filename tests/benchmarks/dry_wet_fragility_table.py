#!/usr/bin/python3
"""The dam blocks over the record suite, dry and under their reservoirs: each limit state's fitted
median, as docs/validation.md shows it, and what each study took.

Not a test: runs, one after another on --ranks ranks, each block's dry record-suite study
(configs/record_suite_study.json for type A, configs/dam_type_b_record_suite.json for type B) and
its reservoir study (configs/dam_type_*_reservoir_study.json: the same records, inputs, levels and
seed, the pool level sampled 0 to 5 m below the crest) once per --uplift rule (the config's
reservoir.uplift replaced; default: unchanged, the configs' own). It prints two markdown tables:
per block and limit state, the fitted median with its 95 % bootstrap interval (in the studies'
intensity measure) and how many samples exceeded it, dry and for each rule (a dry study has no
post-earthquake limit state: "-"); and each study's wall time. With --figures DIR, draws each
block's dry against wet curves (the first rule) into DIR/dam_type_{a,b}_dry_wet_fragility.png
with postproc/plots/plot_fragility_pair.py's --kinds dislocation loss post_earthquake.

    /usr/bin/python3 tests/benchmarks/dry_wet_fragility_table.py --blockfrag build/mpi_driver/blockfrag \\
        [--ranks 2] [--blocks a b] [--uplift unchanged zero_in_gap full_head_in_gap] \\
        [--figures docs] [--keep DIR] [--samples-per-level N] [--markdown]

--markdown prints under each table the line docs/validation.md shows under it: the version that
computed it, the cores and the load average, and this command (tests/benchmarks/markdown_stamp.py).
The studies write into a temporary folder, removed at the end, or into --keep DIR, kept.
--samples-per-level replaces the configs' 36 (a quick check of the whole chain).
"""

import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import h5py
import numpy as np

from markdown_stamp import Stamp

SOURCE = Path(__file__).resolve().parents[2]
CONFIGS = SOURCE / "configs"
BLOCKS = {
    "a": ("type A", CONFIGS / "record_suite_study.json", CONFIGS / "dam_type_a_reservoir_study.json"),
    "b": ("type B", CONFIGS / "dam_type_b_record_suite.json", CONFIGS / "dam_type_b_reservoir_study.json"),
}
UPLIFT_RULES = ("unchanged", "zero_in_gap", "full_head_in_gap", "none")
PLOT = SOURCE / "postproc" / "plots" / "plot_fragility_pair.py"
KINDS = ("dislocation", "loss", "post_earthquake")
# The rows of a block's table, in this order: the limit-state types of the figure's kinds.
ROW_TYPES = ("residual_slide", "overturning", "post_earthquake_unstable")


def run_study(blockfrag, config, output, ranks, samples_per_level):
    """Runs the study; its wall time in seconds."""
    command = [str(Path(blockfrag).resolve()), "run", str(config), "--output", str(output)]
    if samples_per_level:
        command += ["--samples-per-level", str(samples_per_level)]
    if ranks > 1:
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-n", str(ranks)] + command
    start = time.monotonic()
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.exit(f"{config.name}: blockfrag exited with {result.returncode}:\n{result.stderr[-2000:]}")
    return time.monotonic() - start


def with_uplift(config, rule, folder):
    """The reservoir study under an uplift rule: the config itself when it names that rule, else a
    copy in folder with the rule replaced (and the records it names by their absolute paths)."""
    study = json.loads(config.read_text())
    if study["scene"]["reservoir"]["uplift"] == rule:
        return config
    study["scene"]["reservoir"]["uplift"] = rule
    motion = study["scene"]["ground_motion"]
    motion["records"] = [str((config.parent / r).resolve()) for r in motion["records"]]
    path = Path(folder) / f"{config.stem}_{rule}.json"
    path.write_text(json.dumps(study, indent=2))
    return path


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def describe(path):
    """Per limit state (name -> (type, threshold, cell)): its fit and how many exceeded it; and
    the samples' count."""
    cells = {}
    with h5py.File(path, "r") as f:
        samples = 0
        for name, group in f["fragility"].items():
            attrs = group.attrs
            exceedances = int(np.sum(group["exceedances"][()]))
            samples = int(np.sum(group["trials"][()]))
            median = float(attrs["median"])
            if text(attrs["fit_status"]) == "ok" and math.isfinite(median):
                fit = f"{median:.3g}"
                if "median_ci" in attrs:
                    low, high = (float(v) for v in attrs["median_ci"])
                    fit += f" [{low:.3g}, {high:.3g}]"
            else:
                fit = f"no fit ({text(attrs['fit_status'])})"
            cells[name] = (text(attrs["type"]), float(attrs["threshold"]), f"{fit}, {exceedances} of {samples}")
        measure = f["fragility"].attrs
        units = f"{text(measure['im_label'])}, {text(measure['im_units'])}" if "im_label" in measure else ""
    return cells, units, samples


def row_order(described):
    """The limit-state names of any of the block's studies, by ROW_TYPES and then threshold."""
    found = {}
    for cells in described:
        for name, (state_type, threshold, _) in cells.items():
            if state_type in ROW_TYPES:
                found[name] = (ROW_TYPES.index(state_type), threshold)
    return sorted(found, key=lambda name: found[name])


def draw(dry_output, wet_output, label, figure, rule):
    subprocess.run(["/usr/bin/python3", str(PLOT), str(dry_output), str(wet_output), "-o", str(figure),
                    "--labels", f"{label} dry", f"{label} wet", "--kinds", *KINDS,
                    "--title", f"{label} dam block on its dam's crest, 18 records: dry against the "
                    f"reservoir 0-5 m below the crest (uplift {rule})"], check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--blockfrag", required=True, help="the blockfrag executable")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--blocks", nargs="+", choices=list(BLOCKS), default=list(BLOCKS))
    parser.add_argument("--uplift", nargs="+", choices=UPLIFT_RULES, default=["unchanged"],
                        help="the reservoir studies' uplift rules, each a study")
    parser.add_argument("--figures", type=Path, help="folder of the dry/wet PNGs")
    parser.add_argument("--keep", type=Path, help="folder that keeps the studies' outputs")
    parser.add_argument("--samples-per-level", type=int, help="replaces the configs' samples per level")
    parser.add_argument("--markdown", action="store_true", help="the stamp line under each table")
    args = parser.parse_args()
    stamp = Stamp(args.blockfrag, note=f"{args.ranks} ranks") if args.markdown else None
    medians, times = [], []
    with tempfile.TemporaryDirectory(prefix="blockfrag_dry_wet_") as temporary:
        folder = args.keep or Path(temporary)
        folder.mkdir(parents=True, exist_ok=True)
        units = ""
        for block in args.blocks:
            label, dry, wet = BLOCKS[block]
            studies = [("dry", dry, f"configs/{dry.name}")]
            studies += [(f"wet, uplift {rule}", with_uplift(wet, rule, temporary), f"configs/{wet.name}"
                         + ("" if rule == "unchanged" else f" with uplift {rule}")) for rule in args.uplift]
            outputs, described = [], []
            for case, config, shown in studies:
                output = folder / f"{config.stem}.h5"
                seconds = run_study(args.blockfrag, config, output, args.ranks, args.samples_per_level)
                print(f"{label} {case}: {seconds:.0f} s", file=sys.stderr, flush=True)
                cells, units, samples = describe(output)
                outputs.append(output)
                described.append(cells)
                times.append([label, case, shown, str(samples), f"{seconds:.0f}"])
            for name in row_order(described):
                medians.append([label, name] + [cells[name][2] if name in cells else "-" for cells in described])
            if args.figures:
                draw(outputs[0], outputs[1], label, args.figures / f"dam_type_{block}_dry_wet_fragility.png",
                     args.uplift[0])
    unit_text = f" ({units})" if units else ""
    header = ["block", "limit state", f"dry: median{unit_text} [95 % bootstrap], exceeded"]
    header += [f"wet, uplift {rule}: median [95 % bootstrap], exceeded" for rule in args.uplift]
    print_table(header, medians, stamp)
    print()
    print_table(["block", "study", "config", "samples", "wall time (s)"], times, stamp)
    return 0


def print_table(header, rows, stamp):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    print("\n".join(lines))
    if stamp:
        print()
        print(stamp.line())


if __name__ == "__main__":
    sys.exit(main())
