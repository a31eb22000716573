"""The pure parts of scripts/mapping_benchmark.py: the commands of one run (dslam_run_dataset
with --map, --map-unmasked, --grid and --objects, then dslam_eval_objects and dslam_eval_map, the
masked map's with the grid), the numbers
of one run from the tools' JSON files, the mean over seeds, and the Markdown tables."""

import json
import os
import statistics

SCENARIOS = ["walking", "walking_static", "close_person", "walking_halfsphere", "static_room"]

# The columns of the tables: (key of run_numbers(), heading, decimals).
COLUMNS = [
    ("found_share", "found share", 3),
    ("centroid_median_m", "centroid median [m]", 3),
    ("velocity_median_mps", "velocity median [m/s]", 3),
    ("false_share", "false share", 3),
    ("id_switches", "id switches", 1),
    ("ghost_masked", "ghost share masked", 4),
    ("ghost_unmasked", "ghost share unmasked", 4),
    ("coverage_masked", "coverage masked", 3),
    ("coverage_unmasked", "coverage unmasked", 3),
    ("coverage_ratio", "coverage ratio masked / unmasked", 3),
    ("grid_ghost_cells", "grid ghost cells", 1),
    ("unmasked_grid_ghost_cells", "ghost cells unmasked", 1),
    ("grid_precision", "grid precision", 3),
    ("grid_recall", "grid recall", 3),
]


def run_paths(out_dir):
    """The files of one run in `out_dir`, by role."""
    names = {"trajectory": "trajectory.txt", "map": "map.pcd", "map_unmasked": "map_unmasked.pcd",
             "grid": "grid.yaml", "objects": "objects.txt", "summary": "summary.json",
             "eval_objects": "eval_objects.json", "eval_map": "eval_map.json",
             "eval_map_unmasked": "eval_map_unmasked.json"}
    return {role: os.path.join(out_dir, name) for role, name in names.items()}


def run_commands(bin_dir, folder, paths, extra_args=()):
    """The commands of one run, in order: dslam_run_dataset on `folder`, then the object and the
    two map measurements of its outputs (each placed in the world by the run's trajectory)."""
    def tool(name):
        return os.path.join(bin_dir, name)
    run = [tool("dslam_run_dataset"), "--dataset", folder, "--trajectory", paths["trajectory"],
           "--map", paths["map"], "--map-unmasked", paths["map_unmasked"], "--grid", paths["grid"],
           "--objects", paths["objects"], "--summary", paths["summary"], "--quiet"]
    run += list(extra_args)
    common = ["--dataset", folder, "--trajectory", paths["trajectory"]]
    objects = [tool("dslam_eval_objects")] + common + ["--objects", paths["objects"], "--json",
                                                       paths["eval_objects"]]
    masked = [tool("dslam_eval_map")] + common + ["--map", paths["map"], "--grid", paths["grid"],
                                                  "--unmasked-map", paths["map_unmasked"],
                                                  "--json", paths["eval_map"]]
    unmasked = [tool("dslam_eval_map")] + common + ["--map", paths["map_unmasked"], "--json",
                                                    paths["eval_map_unmasked"]]
    return [run, objects, masked, unmasked]


def ratio(numerator, denominator):
    """numerator / denominator; None when either is None or the denominator is 0."""
    if numerator is None or denominator is None or denominator == 0:
        return None
    return numerator / denominator


def run_numbers(eval_objects, eval_map, eval_map_unmasked):
    """The table's numbers of one run from the three JSON objects (dicts) the eval tools wrote;
    values the tools wrote as null (nothing to measure) stay None."""
    return {
        "found_share": eval_objects.get("found_share"),
        "centroid_median_m": eval_objects.get("centroid_error_median_m"),
        "velocity_median_mps": eval_objects.get("velocity_error_median_mps"),
        "false_share": eval_objects.get("false_share"),
        "id_switches": eval_objects.get("id_switches"),
        "ghost_masked": eval_map.get("ghost_share"),
        "ghost_unmasked": eval_map_unmasked.get("ghost_share"),
        "coverage_masked": eval_map.get("static_coverage"),
        "coverage_unmasked": eval_map_unmasked.get("static_coverage"),
        "coverage_ratio": ratio(eval_map.get("static_coverage"),
                                eval_map_unmasked.get("static_coverage")),
        "grid_ghost_cells": eval_map.get("grid_ghost_cells"),
        "unmasked_grid_ghost_cells": eval_map.get("unmasked_grid_ghost_cells"),
        "grid_precision": eval_map.get("grid_precision"),
        "grid_recall": eval_map.get("grid_recall"),
    }


def load_run(paths):
    """run_numbers() of the JSON files of one run (run_paths())."""
    loaded = []
    for role in ("eval_objects", "eval_map", "eval_map_unmasked"):
        with open(paths[role]) as handle:
            loaded.append(json.load(handle))
    return run_numbers(*loaded)


def mean_numbers(runs):
    """Per key, the mean over the runs that have a value (None when none has)."""
    keys = [key for key, _, _ in COLUMNS]
    means = {}
    for key in keys:
        values = [run[key] for run in runs if run.get(key) is not None]
        means[key] = statistics.mean(values) if values else None
    return means


def fmt(value, decimals):
    return "n/a" if value is None else f"{value:.{decimals}f}"


def table(first_heading, rows):
    """A Markdown table: `rows` is a list of (label, numbers) with numbers as run_numbers()."""
    lines = ["| " + " | ".join([first_heading] + [heading for _, heading, _ in COLUMNS]) + " |",
             "|" + "---|" * (len(COLUMNS) + 1)]
    for label, numbers in rows:
        cells = [fmt(numbers.get(key), decimals) for key, _, decimals in COLUMNS]
        lines.append("| " + " | ".join([label] + cells) + " |")
    return "\n".join(lines)


def scenario_table(scenario, seeds, runs):
    """The table of one scenario: one row per seed and their mean."""
    rows = [(f"{scenario} seed {seed}", numbers) for seed, numbers in zip(seeds, runs)]
    rows.append((f"{scenario} mean", mean_numbers(runs)))
    return table("run", rows)


def summary_table(scenario_means):
    """The means of every scenario (a list of (scenario, mean numbers)) and their mean."""
    rows = list(scenario_means)
    rows.append(("mean of the scenarios", mean_numbers([numbers for _, numbers in rows])))
    return table("scenario", rows)
