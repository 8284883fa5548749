package hitbox;

import java.util.Arrays;

/**
 * A map from ids (ints, 0 or more) to slots (ints), for the broad phases: open addressing with
 * linear probing and no boxing. Removal shifts the entries after the hole back (no tombstones),
 * so a map that sees endless adds and removes never needs cleaning. Grows when half full.
 */
final class IdSlots {
    private static final int EMPTY = -1;

    private int[] keys;
    private int[] values;
    private int mask;
    private int size;

    IdSlots() {
        allocate(16);
    }

    /** @return the slot of {@code id}, or -1 if it is not in the map */
    int get(int id) {
        int[] k = keys;
        for (int i = home(id); ; i = (i + 1) & mask) {
            int key = k[i];
            if (key == id) {
                return values[i];
            }
            if (key == EMPTY) {
                return -1;
            }
        }
    }

    /** Maps {@code id} to {@code slot}, replacing what it was mapped to. */
    void put(int id, int slot) {
        if (2 * (size + 1) > keys.length) {
            int[] oldKeys = keys, oldValues = values;
            allocate(keys.length * 2);
            for (int i = 0; i < oldKeys.length; i++) {
                if (oldKeys[i] != EMPTY) {
                    insert(oldKeys[i], oldValues[i]);
                }
            }
        }
        insert(id, slot);
    }

    /** Removes {@code id} if present. */
    void remove(int id) {
        int i = home(id);
        while (keys[i] != id) {
            if (keys[i] == EMPTY) {
                return;
            }
            i = (i + 1) & mask;
        }
        // Backward-shift deletion: move up each later entry of the run that may sit at the hole.
        for (int j = (i + 1) & mask; keys[j] != EMPTY; j = (j + 1) & mask) {
            int h = home(keys[j]);
            boolean between = i <= j ? (i < h && h <= j) : (i < h || h <= j);
            if (!between) {
                keys[i] = keys[j];
                values[i] = values[j];
                i = j;
            }
        }
        keys[i] = EMPTY;
        size--;
    }

    void clear() {
        Arrays.fill(keys, EMPTY);
        size = 0;
    }

    private void insert(int id, int slot) {
        int i = home(id);
        while (keys[i] != EMPTY && keys[i] != id) {
            i = (i + 1) & mask;
        }
        if (keys[i] == EMPTY) {
            keys[i] = id;
            size++;
        }
        values[i] = slot;
    }

    private void allocate(int capacity) {
        keys = new int[capacity];
        Arrays.fill(keys, EMPTY);
        values = new int[capacity];
        mask = capacity - 1;
        size = 0;
    }

    private int home(int id) {
        int h = id * 0x9E3779B9;
        return (h ^ (h >>> 16)) & mask;
    }
}
