package hitbox.internal;

/**
 * A map from pair keys (longs, 0 or more: two non-negative ints, the first above) to slots
 * (ints), for the world's contacts, with no boxing: open addressing, linear probing, removal
 * by shifting the entries after the hole back (no tombstones), as {@link IdSlots} does for ids.
 * It grows when half full and never shrinks, so a world in its steady state allocates nothing.
 */
public final class PairSlots {
    private static final long EMPTY = -1;

    private long[] keys;
    private int[] values;
    private int mask;
    private int size;

    public PairSlots() {
        allocate(64);
    }

    /** The key of a pair of non-negative ints, the first above. */
    public static long key(int first, int second) {
        return ((long) first << 32) | second;
    }

    /** @return how many pairs the map holds */
    public int size() {
        return size;
    }

    /** @return the slot of {@code key}, or -1 if it is not in the map */
    public int get(long key) {
        long[] k = keys;
        for (int i = home(key); ; i = (i + 1) & mask) {
            long at = k[i];
            if (at == key) {
                return values[i];
            }
            if (at == EMPTY) {
                return -1;
            }
        }
    }

    /** Puts a key that is not in the map yet. */
    public void add(long key, int slot) {
        if (2 * (size + 1) > keys.length) {
            grow();
        }
        long[] k = keys;
        int i = home(key);
        while (k[i] != EMPTY) {
            i = (i + 1) & mask;
        }
        k[i] = key;
        values[i] = slot;
        size++;
    }

    /** Removes a key; nothing if it is not there. */
    public void remove(long key) {
        long[] k = keys;
        int i = home(key);
        while (k[i] != key) {
            if (k[i] == EMPTY) {
                return;
            }
            i = (i + 1) & mask;
        }
        // Shift back every entry after the hole that would not be found past it.
        int hole = i;
        for (int j = (hole + 1) & mask; k[j] != EMPTY; j = (j + 1) & mask) {
            int h = home(k[j]);
            boolean movable = hole <= j ? (h <= hole || h > j) : (h <= hole && h > j);
            if (movable) {
                k[hole] = k[j];
                values[hole] = values[j];
                hole = j;
            }
        }
        k[hole] = EMPTY;
        size--;
    }

    private int home(long key) {
        long h = key * 0x9E3779B97F4A7C15L;
        return (int) (h >>> 32) & mask;
    }

    private void grow() {
        long[] oldKeys = keys;
        int[] oldValues = values;
        allocate(2 * oldKeys.length);
        for (int i = 0; i < oldKeys.length; i++) {
            if (oldKeys[i] != EMPTY) {
                add(oldKeys[i], oldValues[i]);
            }
        }
    }

    private void allocate(int capacity) {
        keys = new long[capacity];
        java.util.Arrays.fill(keys, EMPTY);
        values = new int[capacity];
        mask = capacity - 1;
        size = 0;
    }
}
