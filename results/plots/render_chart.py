#!/usr/bin/env python3
"""Render a railsim chart description (JSON written by results/chart.cpp) to PNG."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(path):
    with open(path) as f:
        spec = json.load(f)
    fig, ax = plt.subplots(figsize=(8, 5), dpi=110)
    for s in spec["series"]:
        kw = {"label": s["label"] or None}
        if s.get("color"):
            kw["color"] = s["color"]
        x = [float("nan") if v is None else v for v in s["x"]]
        y = [float("nan") if v is None else v for v in s["y"]]
        style = s.get("style", "line")
        if style == "markers":
            ax.plot(x, y, "o", **kw)
        elif style == "line+markers":
            ax.plot(x, y, "-o", markersize=4, **kw)
        elif style == "step":
            ax.step(x, y, where="post", **kw)
        else:
            ax.plot(x, y, "-", **kw)
    for line in spec.get("lines", []):
        kw = {"color": line.get("color") or "k", "linestyle": "--", "linewidth": 1,
              "label": line.get("label") or None}
        if line.get("vertical", True):
            ax.axvline(line["value"], **kw)
        else:
            ax.axhline(line["value"], **kw)
    for a in spec.get("annotations", []):
        ax.annotate(a["text"], (a["x"], a["y"]), textcoords="offset points", xytext=(5, 5), fontsize=8)
    if spec.get("logx"):
        ax.set_xscale("log")
    if spec.get("logy"):
        ax.set_yscale("log")
    ax.set_title(spec.get("title", ""))
    ax.set_xlabel(spec.get("xlabel", ""))
    ax.set_ylabel(spec.get("ylabel", ""))
    ax.grid(True, which="both", alpha=0.3)
    if any(s["label"] for s in spec["series"]) or any(l.get("label") for l in spec.get("lines", [])):
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(spec["output"])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
