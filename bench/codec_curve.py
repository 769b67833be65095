# A codec's bpp at a PSNR from its measured points, shared by codec_table.py and codec_methods.py.
import math


def at_psnr(points, target):
    """(bpp, psnr) points -> (label, bpp) at `target` dB on their lower-rate envelope, linear in
    (PSNR, log bpp) between two envelope points: '<x' (the cheapest point already beats it) and
    '>x' (no point reaches it, bpp None) outside."""
    # The lower-rate envelope: keep points whose PSNR beats every cheaper point.
    env, best = [], -1e9
    for b, p in sorted(points):
        if p > best:
            env.append((b, p))
            best = p
    if target <= env[0][1]:
        return '<%.3f' % env[0][0], env[0][0]
    if target > env[-1][1]:
        return '>%.3f' % env[-1][0], None
    for (b0, p0), (b1, p1) in zip(env, env[1:]):
        if p0 <= target <= p1:
            t = (target - p0) / (p1 - p0) if p1 > p0 else 0.0
            b = math.exp(math.log(b0) + t * (math.log(b1) - math.log(b0)))
            return '%.3f' % b, b
    return 'n/a', None
