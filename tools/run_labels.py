"""Labels of runs compared side by side, and the split of a per-run table into its runs.

lbdem-compare-runs and lbdem-collision-stats label each run "l = <size_factor>" unless told
otherwise, and write their per-run tables (spectra, impact-speed histograms) run after run with
that label in each row. Two runs with the same size factor then share a label: unique_labels names
them by their folders, and split_runs finds each run's rows by their order, not by the label.
"""
import os
from collections import Counter


def _tail(path, depth):
    parts = os.path.normpath(os.path.abspath(path)).split(os.sep)
    return "/".join(p for p in parts[-depth:] if p)


def unique_labels(labels, run_dirs):
    """The labels, with those that more than one run shares replaced by the runs' folder names
    (the last two path components, or more, where the folder names collide too)."""
    counts = Counter(labels)
    dup = [i for i, lab in enumerate(labels) if counts[lab] > 1]
    if not dup:
        return list(labels)
    others = {lab for lab in labels if counts[lab] == 1}
    out = list(labels)
    for depth in range(1, 64):
        names = [_tail(run_dirs[i], depth) for i in dup]
        if len(set(names)) == len(names) and not set(names) & others:
            break
    for i, name in zip(dup, names):
        out[i] = name
    return out


def split_runs(rows, labels, key):
    """rows (dicts, the runs' blocks one after another, each row with a "label") split into one
    list per run, in the order of `labels` (the runs' labels as the tool wrote them). A block ends
    where the label changes or where key(row) repeats within it (a second run with the same label
    starts its frequencies or bins again). A run whose block is absent gets []."""
    blocks = []
    seen = set()
    for r in rows:
        k = key(r)
        if not blocks or r["label"] != blocks[-1][0]["label"] or k in seen:
            blocks.append([])
            seen = set()
        blocks[-1].append(r)
        seen.add(k)
    out = []
    b = 0
    for lab in labels:
        if b < len(blocks) and blocks[b][0]["label"] == lab:
            out.append(blocks[b])
            b += 1
        else:
            out.append([])
    return out
