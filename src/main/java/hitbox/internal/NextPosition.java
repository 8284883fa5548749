package hitbox.internal;

/**
 * The tutorial's next-position check against one box, one axis at a time, in
 * {@link SideSets}' bits ({@code LEFT_RIGHT} for a blocked move across, {@code TOP_BOTTOM}
 * down, both for a diagonal hit on a corner): the kernel behind {@code Motion} and its
 * broad-phase form. Nothing is checked or allocated; a NaN blocks nothing.
 */
public final class NextPosition {
    private NextPosition() {
    }

    /** The axes a box moving by (vx, vy) would be blocked on by the box (ox, oy, ow, oh). */
    public static int rect(float x, float y, float w, float h, float vx, float vy,
                           float ox, float oy, float ow, float oh) {
        if (Check.nan(x, y, w, h, vx) || Check.nan(vy, ox, oy, ow, oh)) {
            return 0;
        }
        float nx = x + vx;
        float ny = y + vy;
        int blocked = (RawTests.rectRect(nx, y, w, h, ox, oy, ow, oh) ? SideSets.LEFT_RIGHT : 0)
                | (RawTests.rectRect(x, ny, w, h, ox, oy, ow, oh) ? SideSets.TOP_BOTTOM : 0);
        if (blocked == 0 && RawTests.rectRect(nx, ny, w, h, ox, oy, ow, oh)) {
            return SideSets.ALL;
        }
        return blocked;
    }

    /** The axes a circle moving by (vx, vy) would be blocked on by the box (ox, oy, ow, oh). */
    public static int circle(float cx, float cy, float r, float vx, float vy,
                             float ox, float oy, float ow, float oh) {
        if (Check.nan(cx, cy, r, vx, vy) || Check.nan(ox, oy, ow, oh, 0)) {
            return 0;
        }
        float nx = cx + vx;
        float ny = cy + vy;
        int blocked = (RawTests.circleRect(nx, cy, r, ox, oy, ow, oh) ? SideSets.LEFT_RIGHT : 0)
                | (RawTests.circleRect(cx, ny, r, ox, oy, ow, oh) ? SideSets.TOP_BOTTOM : 0);
        if (blocked == 0 && RawTests.circleRect(nx, ny, r, ox, oy, ow, oh)) {
            return SideSets.ALL;
        }
        return blocked;
    }
}
