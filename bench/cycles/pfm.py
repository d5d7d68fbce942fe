"""Reading PFM images (what build_scene.py and `ptview render --out x.pfm` write) into numpy."""
import numpy as np


def read_pfm(path):
    """The image as a float64 array of shape (height, width, 3), rows as stored (bottom first)."""
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            raise SystemExit(f"{path}: not a colour PFM")
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    return data.reshape(height, width, 3).astype(np.float64)
