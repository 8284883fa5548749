package hitbox;

import hitbox.internal.*;

import java.math.BigDecimal;

/**
 * SeparatingAxis.contact on raw vertices as of commit 9c3ead8, the reference
 * {@link SeparatingAxisAgreementTest} compares with: every edge normal of both polygons, both
 * ways along each, every vertex projected.
 */
final class SeparatingAxisOld {
    private SeparatingAxisOld() {
    }

    static Contact contact(double[] a, double[] b) {
        double bestX = 0, bestY = 0, best = Double.POSITIVE_INFINITY;
        for (int pass = 0; pass < 2; pass++) {
            double[] owner = pass == 0 ? a : b;
            int n = owner.length / 2;
            for (int i = 0; i < n; i++) {
                int j = i + 1 == n ? 0 : i + 1;
                double mx = -(owner[2 * j + 1] - owner[2 * i + 1]);
                double my = owner[2 * j] - owner[2 * i];
                if (mx == 0 && my == 0) {
                    continue;
                }
                double minA = Double.POSITIVE_INFINITY, maxA = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < a.length - 1; k += 2) {
                    double v = a[k] * mx + a[k + 1] * my;
                    minA = v < minA ? v : minA;
                    maxA = v > maxA ? v : maxA;
                }
                double minB = Double.POSITIVE_INFINITY, maxB = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < b.length - 1; k += 2) {
                    double v = b[k] * mx + b[k + 1] * my;
                    minB = v < minB ? v : minB;
                    maxB = v > maxB ? v : maxB;
                }
                double forward = maxA - minB, back = maxB - minA;
                double bound = 1e-14 * Math.max(Math.max(Math.abs(minA), Math.abs(maxA)), Math.max(Math.abs(minB), Math.abs(maxB)));
                if (Math.abs(forward) <= bound || Math.abs(back) <= bound) {
                    BigDecimal[] exact = exactOverlaps(owner, i, j, a, b);
                    forward = exact[0].doubleValue();
                    back = exact[1].doubleValue();
                    if (exact[0].signum() <= 0 || exact[1].signum() <= 0) {
                        return null;
                    }
                } else if (forward <= 0 || back <= 0) {
                    return null;
                }
                double len = Math.sqrt(mx * mx + my * my);
                double ux = mx / len, uy = my / len, d = forward / len;
                if (Contacts.Shortest.beats(ux, uy, d, bestX, bestY, best, 0, false)) {
                    bestX = ux;
                    bestY = uy;
                    best = d;
                }
                d = back / len;
                if (Contacts.Shortest.beats(-ux, -uy, d, bestX, bestY, best, 0, false)) {
                    bestX = -ux;
                    bestY = -uy;
                    best = d;
                }
            }
        }
        return best == Double.POSITIVE_INFINITY ? null : Contacts.of(bestX, bestY, best);
    }

    private static BigDecimal[] exactOverlaps(double[] owner, int i, int j, double[] a, double[] b) {
        BigDecimal mx = new BigDecimal(owner[2 * i + 1]).subtract(new BigDecimal(owner[2 * j + 1]));
        BigDecimal my = new BigDecimal(owner[2 * j]).subtract(new BigDecimal(owner[2 * i]));
        BigDecimal[] sa = shadow(a, mx, my), sb = shadow(b, mx, my);
        return new BigDecimal[] {sa[1].subtract(sb[0]), sb[1].subtract(sa[0])};
    }

    private static BigDecimal[] shadow(double[] p, BigDecimal mx, BigDecimal my) {
        BigDecimal lo = null, hi = null;
        for (int k = 0; k < p.length; k += 2) {
            BigDecimal v = new BigDecimal(p[k]).multiply(mx).add(new BigDecimal(p[k + 1]).multiply(my));
            lo = lo == null || v.compareTo(lo) < 0 ? v : lo;
            hi = hi == null || v.compareTo(hi) > 0 ? v : hi;
        }
        return new BigDecimal[] {lo, hi};
    }
}
