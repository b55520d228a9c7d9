"""The learned inpainter's network, as filter_curvature_inpaint/inpaint/curvature_unet.h runs it.

Per level two 3x3 convolutions with ReLU, then a 2x2 average pool; two at the bottom; per level
back up a nearest-neighbour doubling with the level's skip appended after it and two 3x3
convolutions with ReLU; last a 1x1 convolution to one channel. Export writes the weights in the
layers' order, in the format CurvatureUNet reads.
"""
import struct

import torch
import torch.nn as nn
import torch.nn.functional as F

INPUT_CHANNELS = 3  # the image's curvature, the hole's share, the continuation


class CurvatureUNet(nn.Module):
    def __init__(self, widths=(8, 16, 32, 64), bottom=64):
        super().__init__()
        self.widths = list(widths)
        self.down = nn.ModuleList()
        cin = INPUT_CHANNELS
        for w in widths:
            self.down.append(nn.ModuleList([nn.Conv2d(cin, w, 3, padding=1),
                                            nn.Conv2d(w, w, 3, padding=1)]))
            cin = w
        self.bottom = nn.ModuleList([nn.Conv2d(cin, bottom, 3, padding=1),
                                     nn.Conv2d(bottom, bottom, 3, padding=1)])
        cin = bottom
        self.up = nn.ModuleList()
        for w in reversed(widths):
            self.up.append(nn.ModuleList([nn.Conv2d(cin + w, w, 3, padding=1),
                                          nn.Conv2d(w, w, 3, padding=1)]))
            cin = w
        self.out = nn.Conv2d(cin, 1, 1)

    def forward(self, x):
        skips = []
        for a, b in self.down:
            x = F.relu(b(F.relu(a(x))))
            skips.append(x)
            x = F.avg_pool2d(x, 2)
        a, b = self.bottom
        x = F.relu(b(F.relu(a(x))))
        for (a, b), skip in zip(self.up, reversed(skips)):
            x = torch.cat([F.interpolate(x, scale_factor=2, mode="nearest"), skip], 1)
            x = F.relu(b(F.relu(a(x))))
        return self.out(x)

    def convolutions(self):
        for pair in list(self.down) + [self.bottom] + list(self.up):
            yield from pair
        yield self.out


def export(model, path):
    """Writes the weights as CurvatureUNet reads them (little-endian)."""
    with open(path, "wb") as f:
        f.write(b"CIUN")
        f.write(struct.pack("<ii", 1, len(model.widths)))
        for conv in model.convolutions():
            w = conv.weight.detach().float().contiguous()
            f.write(struct.pack("<iii", w.shape[0], w.shape[1], w.shape[2]))
            f.write(w.numpy().astype("<f4").tobytes())
            f.write(conv.bias.detach().float().numpy().astype("<f4").tobytes())


def check_input(side=128):
    """The input that tests/learned_inpainter_test.cpp feeds the network too."""
    import math
    x = torch.zeros(1, INPUT_CHANNELS, side, side)
    for c in range(INPUT_CHANNELS):
        for r in range(side):
            for q in range(side):
                if c == 1:
                    v = 1.0 if (q - 64) ** 2 + (r - 64) ** 2 < 40 ** 2 else 0.0
                else:
                    v = 0.5 + 0.3 * math.sin(0.05 * (q + 1) * (c + 1) + 0.07 * r)
                x[0, c, r, q] = v
    return x


def write_check(model, path):
    """The network's output at 16 cells of check_input(): "row column value" lines."""
    with torch.no_grad():
        y = model(check_input())[0, 0]
    with open(path, "w") as f:
        for r in range(4, 128, 32):
            for q in range(4, 128, 32):
                f.write("%d %d %.7g\n" % (r, q, float(y[r, q])))
