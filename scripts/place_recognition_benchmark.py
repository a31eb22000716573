#!/usr/bin/env python3
"""Place recognition benchmark: the vocabulary's top-1 / top-3 hits on held-out sequences with
ground truth, through dslam_place_recognition_eval (docs/tools-and-data.md, "Place
recognition"). On room_tour (seeds --seeds, 728 frames, rendered once into --cache unless
--room-tour-folders names the folders) every 10th frame of 0..400 is the database and every 10th
of 560..727 a query (the second lap re-visits the first views); on the shared Bonn segment
(../shared/data/bonn_crowd_frames300-599, when present; the camera stays in one place) every 10th
of 0..140 is the database and every 10th of 150..299 a query. A candidate is true within 0.3 m and
20 deg. Prints a Markdown table. Usage:
  scripts/place_recognition_benchmark.py [--vocabulary FILE] [--seeds 1 2 3 4 5]
                                         [--room-tour-folders DIR ...]
                                         [--cache build/place_recognition_bench]
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark import BIN, REPO, SHARED, render, run  # noqa: E402

SUMMARY = re.compile(
    r"summary: (\d+) queries, database (\d+) frames, (\d+) queries with a true frame in it: "
    r"top-1 (\d+), top-3 (\d+), best true above best false (\d+); median best true score "
    r"([\d.]+), median best false score ([\d.]+) \(vocabulary (\w+)\)")
COLUMNS = ("queries", "database", "answerable", "top1", "top3", "separated", "true", "false")


def evaluate(folder, vocabulary, database, queries):
    """The summary numbers of dslam_place_recognition_eval on `folder` and the identity."""
    cmd = [os.path.join(BIN, "dslam_place_recognition_eval"), "--dataset", folder,
           "--database", database, "--queries", queries]
    if vocabulary:
        cmd += ["--vocabulary", vocabulary]
    match = SUMMARY.search(run(cmd))
    if not match:
        sys.exit(f"no summary from {' '.join(cmd)}")
    values = [int(x) for x in match.groups()[:6]] + [float(x) for x in match.groups()[6:8]]
    return dict(zip(COLUMNS, values)), match.group(9)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--vocabulary", default="", help="default: the committed vocabulary")
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4, 5])
    parser.add_argument("--room-tour-folders", nargs="+", default=[])
    parser.add_argument("--cache", default=os.path.join(REPO, "build", "place_recognition_bench"))
    args = parser.parse_args()
    folders = args.room_tour_folders or [render("room_tour", seed, 728, args.cache)
                                         for seed in args.seeds]
    sequences = [(os.path.basename(f), f, "0:400:10", "560:727:10") for f in folders]
    bonn = os.path.join(SHARED, "bonn_crowd_frames300-599")
    if os.path.exists(os.path.join(bonn, "rgb.txt")):
        sequences.append(("bonn_crowd_frames300-599", bonn, "0:140:10", "150:299:10"))
    print("| sequence | queries | with a true frame | top-1 | top-3 | best true > best false | "
          "median best true score | median best false score |")
    print("|---|---|---|---|---|---|---|---|")
    identity = ""
    for name, folder, database, queries in sequences:
        r, identity = evaluate(folder, args.vocabulary, database, queries)
        print(f"| {name} | {r['queries']} | {r['answerable']} | {r['top1']} | {r['top3']} | "
              f"{r['separated']} | {r['true']:.3f} | {r['false']:.3f} |")
    print(f"\nvocabulary {args.vocabulary or 'committed'}, identity {identity}")


if __name__ == "__main__":
    main()
