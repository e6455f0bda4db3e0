# Relative RMS error of 8x8-pixel block means between two PFM images, as the bench's
# relativeBlockError (src/render/image_compare.cpp) computes it, and the ratio of the images' totals.
# Usage: python3 block_error.py CANDIDATE.pfm REFERENCE.pfm
import sys, struct, math

def readpfm(path):
    f = open(path, 'rb')
    kind = f.readline().strip()
    w, h = map(int, f.readline().split())
    scale = float(f.readline())
    n = w * h * (3 if kind == b'PF' else 1)
    return w, h, struct.unpack(('<' if scale < 0 else '>') + '%df' % n, f.read(4 * n))

def block_error(a, b, w, h, block=8):
    diff = mag = 0.0
    for by in range(0, h - block + 1, block):
        for bx in range(0, w - block + 1, block):
            g = [0.0] * 3
            r = [0.0] * 3
            for y in range(by, by + block):
                for x in range(bx, bx + block):
                    i = 3 * (y * w + x)
                    for c in range(3):
                        g[c] += a[i + c]
                        r[c] += b[i + c]
            diff += sum((g[c] - r[c]) ** 2 for c in range(3))
            mag += sum(r[c] ** 2 for c in range(3))
    return math.sqrt(diff / mag)

w, h, a = readpfm(sys.argv[1])
w2, h2, b = readpfm(sys.argv[2])
assert (w, h) == (w2, h2), "the images differ in size"
print("block error %.4f  total ratio %.4f" % (block_error(a, b, w, h), sum(a) / sum(b)))
