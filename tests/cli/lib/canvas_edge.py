"""Checks that nothing is drawn on the outermost 2 pixels of each PNG (run by tests/cli/figures_canvas.sh; not
a test itself): every pixel there must have the background's colour, the top-left pixel's (white on kerf's
figures). Ink there means a title, axis label, tick label or legend runs off the canvas. Prints one line per PNG
that fails (its size, how many pixels, where) and exits 1 if any did.
Usage: python3 canvas_edge.py PNG..."""
import sys

import numpy as np
from PIL import Image

failed = 0
for path in sys.argv[1:]:
    rgb = np.asarray(Image.open(path).convert("RGB")).astype(int)
    height, width, _ = rgb.shape
    edge = np.ones((height, width), bool)
    edge[2:height - 2, 2:width - 2] = False
    off = edge & (np.abs(rgb - rgb[0, 0]).max(axis=2) > 0)
    rows, cols = np.nonzero(off)
    if len(rows):
        failed += 1
        sides = sorted({name for name, hit in (("left", cols.min() < 2), ("right", cols.max() >= width - 2),
                                               ("top", rows.min() < 2), ("bottom", rows.max() >= height - 2)) if hit})
        print(f"{path} ({width}x{height}): {len(rows)} pixels of the outer 2-pixel frame are not the background "
              f"{tuple(rgb[0, 0])} ({', '.join(sides)}; first at x={cols[0]}, y={rows[0]})")
sys.exit(1 if failed else 0)
