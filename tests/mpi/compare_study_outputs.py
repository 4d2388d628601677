"""Compares study outputs bitwise: every dataset under /samples, /results, /fragility and (of an
adaptive study) /adaptive, (of a surface study) /fragility_surface (values and dtypes, NaN equal to
NaN by bit pattern), the fragility and surface attributes, and the config hash.

usage: compare_study_outputs.py REFERENCE.h5 OTHER.h5 [OTHER.h5 ...]
Also checks that each file's sample columns cover every sample exactly once (the level column is
i // samples_per_level for i = 0..total-1), so a missing or duplicated sample cannot pass, and that
the limit states nest: at every level of a stripe study, each limit state an overturned block
exceeds (overturned_exceeds 1) counts at least the level's overturned samples, so P(any limit
state) >= P(overturning); a residual slide's and a post-earthquake instability's counts are
recounted from /results. A surface
study's grid counts are recounted from /results per cell, and sum to /fragility's per level.
"""
import sys

import h5py
import numpy as np


def datasets(f):
    found = {}
    for group in ("samples", "results", "fragility", "adaptive", "fragility_surface"):
        if group not in f:
            continue
        f[group].visititems(lambda name, obj: found.__setitem__(f"{group}/{name}", obj[()])
                            if isinstance(obj, h5py.Dataset) else None)
    return found


def fragility_attributes(f):
    groups = [f"fragility/{name}" for name in f["fragility"]]
    if "fragility_surface" in f:
        groups += [f"fragility_surface/{name}" for name in f["fragility_surface"]]
    return {group: dict(f[group].attrs) for group in groups}


def same_bits(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def check_complete(path, f):
    total = int(f.attrs["total_samples"])
    n = int(f.attrs["samples_per_level"])
    expected_level = np.arange(total) // n
    for name, obj in datasets(f).items():
        if name.startswith(("samples/", "results/")) and obj.shape != (total,):
            sys.exit(f"{path}: {name} has shape {obj.shape}, expected ({total},)")
    if not np.array_equal(f["samples/level"][()], expected_level):
        sys.exit(f"{path}: /samples/level is not i // {n}: a sample is missing, duplicated or out of place")
    for name in f["fragility"]:
        trials = f["fragility"][name]["trials"][()]
        ok = int(np.sum(f["results/status"][()] == 0))
        if int(trials.sum()) != ok:
            sys.exit(f"{path}: /fragility/{name}: {trials.sum()} trials for {ok} successful samples")
    check_nested(path, f)
    if "fragility_surface" in f:
        check_surface(path, f)


def lost(f):
    """The blocks that overturned or fell off their seat: both count as overturning
    (mpi_driver/study/limit_states.cpp)."""
    return (f["results/overturned"][()] != 0) | (f["results/fell"][()] != 0)


def exceeded(f, group):
    """Which samples exceed the limit state, recounted from /results (successful ones only)."""
    ok = f["results/status"][()] == 0
    overturned = ok & lost(f)
    nested = group.attrs["type"] != "overturning" and group.attrs["overturned_exceeds"]
    if group.attrs["type"] == "overturning":
        return overturned
    if group.attrs["type"] == "residual_slide":
        raw = ok & (np.abs(f["results/final_slide"][()]) > group.attrs["threshold"])
    elif group.attrs["type"] == "post_earthquake_unstable":
        with np.errstate(invalid="ignore"):
            raw = ok & (f["results/post_earthquake_safety_factor"][()] < group.attrs["threshold"])
    else:
        return None  # a rotation limit needs each sample's alpha: not recounted here
    return raw | overturned if nested else raw


def check_surface(path, f):
    ok = f["results/status"][()] == 0
    cells = f["samples/level"][()]
    for name in f["fragility_surface"]:
        group = f["fragility_surface"][name]
        n1, n2 = len(group["im1"]), len(group["im2"])
        trials = group["trials"][()]
        if trials.shape != (n1, n2):
            sys.exit(f"{path}: /fragility_surface/{name}/trials has shape {trials.shape}")
        if not np.array_equal(trials.ravel(), np.bincount(cells[ok], minlength=n1 * n2)):
            sys.exit(f"{path}: /fragility_surface/{name}: trials are not the successful samples per cell")
        for key in ("trials", "exceedances"):
            if not np.array_equal(group[key][()].sum(axis=1), f["fragility"][name][key][()]):
                sys.exit(f"{path}: /fragility/{name}/{key} is not the surface's summed over im2")
        mask = exceeded(f, group)
        if mask is not None and not np.array_equal(
                group["exceedances"][()].ravel(), np.bincount(cells[mask], minlength=n1 * n2)):
            sys.exit(f"{path}: /fragility_surface/{name}: exceedances are not recounted from /results")
        im2 = f["samples/im2"][()]
        if not np.array_equal(im2, group["im2"][()][cells % n2]):
            sys.exit(f"{path}: /samples/im2 is not the period of each sample's cell")


def check_nested(path, f):
    if f["fragility"].attrs["scaling"] != "stripes":
        return
    ok = f["results/status"][()] == 0
    overturned = ok & lost(f)
    levels = f["samples/level"][()]
    if "fragility_surface" in f:  # a surface's cells, to the first measure's levels
        levels = levels // len(next(iter(f["fragility_surface"].values()))["im2"])
    count = lambda mask: np.bincount(levels[mask], minlength=int(levels.max()) + 1)
    for name in f["fragility"]:
        group = f["fragility"][name]
        nested = group.attrs["type"] != "overturning" and group.attrs["overturned_exceeds"]
        exceedances = group["exceedances"][()]
        if nested and np.any(exceedances < count(overturned)):
            sys.exit(f"{path}: /fragility/{name}: fewer exceedances than overturned samples at a "
                     "level: the limit states do not nest")
        if group.attrs["type"] == "residual_slide":
            slid = ok & (np.abs(f["results/final_slide"][()]) > group.attrs["threshold"])
            if not np.array_equal(exceedances, count(slid | overturned if nested else slid)):
                sys.exit(f"{path}: /fragility/{name}: exceedances are not the samples whose "
                         "|final_slide| exceeds the threshold" + (" or that overturned" if nested else ""))
        if group.attrs["type"] == "post_earthquake_unstable":
            with np.errstate(invalid="ignore"):
                unstable = ok & (f["results/post_earthquake_safety_factor"][()] < group.attrs["threshold"])
            if not np.array_equal(exceedances, count(unstable | overturned if nested else unstable)):
                sys.exit(f"{path}: /fragility/{name}: exceedances are not the samples whose "
                         "post-earthquake safety factor is below the threshold" +
                         (" or that overturned" if nested else ""))

def main():
    reference_path, others = sys.argv[1], sys.argv[2:]
    with h5py.File(reference_path, "r") as reference:
        check_complete(reference_path, reference)
        ref_data = datasets(reference)
        ref_attrs = fragility_attributes(reference)
        ref_hash = reference.attrs["config_hash"]
        for path in others:
            with h5py.File(path, "r") as other:
                check_complete(path, other)
                data = datasets(other)
                if sorted(data) != sorted(ref_data):
                    sys.exit(f"{path}: datasets {sorted(data)} differ from {sorted(ref_data)}")
                for name, values in ref_data.items():
                    if not same_bits(values, data[name]):
                        sys.exit(f"{path}: /{name} differs from {reference_path}")
                attrs = fragility_attributes(other)
                for group, group_attrs in ref_attrs.items():
                    for key, value in group_attrs.items():
                        if not same_bits(value, attrs[group][key]):
                            sys.exit(f"{path}: /{group} attribute {key} differs")
                if other.attrs["config_hash"] != ref_hash:
                    sys.exit(f"{path}: config_hash differs")
    print(f"identical: {reference_path} and {len(others)} other file(s)")


if __name__ == "__main__":
    main()
