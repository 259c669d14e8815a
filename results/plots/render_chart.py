#!/usr/bin/env python3
"""Render railsim chart descriptions (JSON written by results/chart.cpp) to PNG.

Usage: render_chart.py SPEC.json [SPEC.json ...] (several charts, one process).

A single plot, or with a non-empty "panels" list a grid of sub-plots with
shared axes (small multiples): each series and annotation names its panel.
"""
import json
import math
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def numbers(values):
    return [float("nan") if v is None else v for v in values]


def plot_series(ax, s):
    kw = {"label": s["label"] or None}
    if s.get("color"):
        kw["color"] = s["color"]
    x = numbers(s["x"])
    y = numbers(s["y"])
    style = s.get("style", "line")
    if style.startswith("custom:"):
        opts = {}
        for item in style[len("custom:"):].split(";"):
            key, _, value = item.partition("=")
            opts[key] = value
        kw["linestyle"] = opts.get("line") or "none"
        if opts.get("marker"):
            kw["marker"] = opts["marker"]
            if opts.get("size"):
                kw["markersize"] = float(opts["size"])
            if "open" in opts:
                kw["markerfacecolor"] = "none"
        ax.plot(x, y, **kw)
    elif style == "dashed":
        ax.plot(x, y, "--", linewidth=1.5, **kw)
    elif style == "dotted":
        ax.plot(x, y, ":", linewidth=1.5, **kw)
    elif style == "faint":
        ax.plot(x, y, "-", linewidth=0.6, alpha=0.3, **kw)
    elif style == "markers":
        ax.plot(x, y, "o", **kw)
    elif style == "crosses":
        ax.plot(x, y, "x", markersize=6, **kw)
    elif style == "line+markers":
        ax.plot(x, y, "-o", markersize=4, **kw)
    elif style == "step":
        ax.step(x, y, where="post", **kw)
    else:
        ax.plot(x, y, "-", **kw)


def shade(ax, spec):
    """Shaded x ranges (curves, transitions, defects); one legend entry per label."""
    seen = set()
    for sp in spec.get("spans", []):
        label = sp.get("label") or None
        if label in seen:
            label = None
        else:
            seen.add(label)
        kw = {"color": sp.get("color") or "0.8", "alpha": sp.get("alpha", 0.2), "label": label, "linewidth": 0,
              "zorder": 0}
        if sp.get("hatch"):
            kw["hatch"] = sp["hatch"]
            kw["fill"] = False
            kw["edgecolor"] = kw.pop("color")
        ax.axvspan(sp["x0"], sp["x1"], **kw)


def plot_band(ax, b):
    ax.fill_between(numbers(b["x"]), numbers(b["y_low"]), numbers(b["y_high"]), color=b.get("color") or "0.6",
                    alpha=b.get("alpha", 0.35), linewidth=0, label=b.get("label") or None)


def decorate(ax, spec):
    shade(ax, spec)
    for line in spec.get("lines", []):
        kw = {"color": line.get("color") or "k", "linestyle": "--", "linewidth": 1,
              "label": line.get("label") or None}
        if line.get("vertical", True):
            ax.axvline(line["value"], **kw)
        else:
            ax.axhline(line["value"], **kw)
    if spec.get("logx"):
        ax.set_xscale("log")
    if spec.get("logy"):
        ax.set_yscale("log")
    ax.grid(True, which="both", alpha=0.3)
    if spec.get("y_from_zero"):
        ax.set_ylim(bottom=0)


def annotate(fig, ax, annotations):
    """Label points; a label that would overlap an earlier one moves up (in points)."""
    fig.canvas.draw()  # fixes the axis limits and the data-to-display transform
    placed = []  # (x, y) of label anchors in display pixels
    px_per_pt = fig.dpi / 72.0
    for a in annotations:
        if a["x"] is None or a["y"] is None:
            continue
        x, y = ax.transData.transform((a["x"], a["y"]))
        dy = 5
        width = 6.5 * len(a["text"]) * px_per_pt  # rough text width at fontsize 8
        while any(abs(x - px) < width and abs(y + dy * px_per_pt - py) < 9 * px_per_pt for px, py in placed):
            dy += 9
        placed.append((x, y + dy * px_per_pt))
        arrow = {"arrowstyle": "-", "lw": 0.5, "color": "0.5"} if dy > 5 else None
        ax.annotate(a["text"], (a["x"], a["y"]), textcoords="offset points", xytext=(5, dy), fontsize=8,
                    arrowprops=arrow)


def single(spec):
    outside = spec.get("legend") == "outside"
    size = spec.get("size") or ([11, 5] if outside else [8, 5])
    fig, ax = plt.subplots(figsize=(size[0], size[1]), dpi=110)
    for b in spec.get("bands", []):
        plot_band(ax, b)
    for s in spec["series"]:
        plot_series(ax, s)
    decorate(ax, spec)
    annotate(fig, ax, spec.get("annotations", []))
    ax.set_title(spec.get("title", ""))
    ax.set_xlabel(spec.get("xlabel", ""))
    ax.set_ylabel(spec.get("ylabel", ""))
    bottom = 0.0
    if spec.get("note"):
        # The note under the plot, wrapped to the figure width.
        text = "\n".join(textwrap.wrap(spec["note"], width=int(size[0] * 15)))
        lines = text.count("\n") + 1
        bottom = min(0.35, (lines * 9.5 + 8) / (size[1] * 72))
        fig.text(0.01, 0.01, text, fontsize=7, va="bottom", ha="left")
    labels = ([s["label"] for s in spec["series"] if s["label"]]
              + [l["label"] for l in spec.get("lines", []) if l.get("label")]
              + sorted({sp["label"] for sp in spec.get("spans", []) if sp.get("label")})
              + [b["label"] for b in spec.get("bands", []) if b.get("label")])
    if labels:
        if outside or (len(labels) > 7 and not spec.get("legend_location")):
            ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
            outside = True
        else:
            ax.legend(fontsize=7, loc=spec.get("legend_location") or "best")
    fig.tight_layout(rect=(0, bottom, 1, 1))
    fig.railsim_tight = outside
    return fig


def multiples(spec):
    titles = spec["panels"]
    n = len(titles)
    ncols = spec.get("panel_columns") or math.ceil(math.sqrt(n))
    nrows = math.ceil(n / ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(3.2 * ncols + 1, 2.7 * nrows + 1), dpi=110,
                             sharex=True, sharey=True, squeeze=False)
    flat = [ax for row in axes for ax in row]
    for i, ax in enumerate(flat):
        if i >= n:
            ax.set_visible(False)
            continue
        ax.set_title(titles[i], fontsize=9)
        decorate(ax, spec)
    for b in spec.get("bands", []):
        p = b.get("panel", 0)
        if 0 <= p < n:
            plot_band(flat[p], b)
    for s in spec["series"]:
        p = s.get("panel", 0)
        if 0 <= p < n:
            plot_series(flat[p], s)
    for a in spec.get("annotations", []):
        p = a.get("panel", 0)
        if 0 <= p < n:
            flat[p].annotate(a["text"], (a["x"], a["y"]), textcoords="offset points", xytext=(3, 3), fontsize=7)
    fig.suptitle(spec.get("title", ""))
    fig.supxlabel(spec.get("xlabel", ""))
    fig.supylabel(spec.get("ylabel", ""))
    # One legend for the figure: the first occurrence of every label.
    handles, labels = [], []
    for ax in flat[:n]:
        for h, l in zip(*ax.get_legend_handles_labels()):
            if l not in labels:
                handles.append(h)
                labels.append(l)
    if labels:
        fig.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, 0.955), ncol=min(len(labels), 4),
                   fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0, 1, 0.93 if labels else 0.97))
    return fig


def render(path):
    with open(path) as f:
        spec = json.load(f)
    # The PNG goes next to its description unless the description names a full path.
    if not os.path.isabs(spec["output"]):
        spec["output"] = os.path.join(os.path.dirname(os.path.abspath(path)), spec["output"])
    if spec.get("panels"):
        fig = multiples(spec)
    else:
        fig = single(spec)
    kw = {"bbox_inches": "tight"} if getattr(fig, "railsim_tight", False) else {}
    save(fig, spec["output"], kw)
    plt.close(fig)


class WriteError(Exception):
    """The PNG could not be written (disk full, no permission): exit status 3."""


def save(fig, out, kw):
    # Through a temporary name and a rename, so that a reader never sees half a
    # PNG; a device or pipe (e.g. /dev/full) is written in place.
    in_place = os.path.exists(out) and not os.path.isfile(out)
    target = out if in_place else f"{out}.tmp.{os.getpid()}"
    try:
        fig.savefig(target, format="png", **kw)
        if not in_place:
            os.replace(target, out)
    except OSError as e:
        if not in_place and os.path.isfile(target):
            os.remove(target)
        raise WriteError(f"{out}: write failed ({e.strerror or e})") from e


def main(paths):
    """Render every chart description given (one process for several charts).
    Exit status 0: all rendered; 3: a PNG could not be written (each such file
    named on a line "PATH: write failed (reason)"); 1: other failures."""
    failed = write_failed = 0
    for path in paths:
        try:
            render(path)
        except WriteError as e:
            print(f"render_chart.py: {e}", file=sys.stderr)
            write_failed += 1
        except Exception as e:  # one bad chart must not cost the others
            print(f"render_chart.py: {path}: {e}", file=sys.stderr)
            failed += 1
    return 3 if write_failed else 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
