package hitbox.internal;

import java.util.Arrays;

/**
 * A map from ids (ints, 0 or more) to slots (ints), for the broad phases, with no boxing.
 *
 * <p>Small ids, the usual 0 to n - 1, are looked up directly in an array ({@code direct}),
 * which grows to cover ids up to a few times the number stored, never more. Other ids go to a
 * hash table with open addressing and linear probing; removal shifts the entries after the hole
 * back (no tombstones), so endless adds and removes never need cleaning. It grows when half full.
 */
public final class IdSlots {
    private static final int EMPTY = -1;

    private int[] direct = new int[0];
    private int directCount;
    private int[] keys;
    private int[] values;
    private int mask;
    private int size;

    public IdSlots() {
        allocate(16);
    }

    /** @return the slot of {@code id}, or -1 if it is not in the map */
    public int get(int id) {
        if (id < direct.length) {
            return direct[id];
        }
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
    public void put(int id, int slot) {
        if (id >= direct.length && id < 4 * (directCount + size + 16)) {
            growDirect(id);
        }
        if (id < direct.length) {
            directCount += direct[id] == EMPTY ? 1 : 0;
            direct[id] = slot;
            return;
        }
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

    /** Covers ids up to {@code id} directly, moving those ids out of the hash table. */
    private void growDirect(int id) {
        int old = direct.length;
        direct = Arrays.copyOf(direct, Math.max(64, Integer.highestOneBit(id) * 2));
        Arrays.fill(direct, old, direct.length, EMPTY);
        for (int i = 0; i < keys.length; i++) {
            int key = keys[i];
            if (key != EMPTY && key < direct.length) {
                direct[key] = values[i];
                directCount++;
            }
        }
        for (int key = old; key < direct.length; key++) {
            if (direct[key] != EMPTY) {
                removeHashed(key);  // from the hash table: the direct array has it now
            }
        }
    }

    /** Removes {@code id} if present. */
    public void remove(int id) {
        if (id < direct.length) {
            directCount -= direct[id] == EMPTY ? 0 : 1;
            direct[id] = EMPTY;
            return;
        }
        removeHashed(id);
    }

    private void removeHashed(int id) {
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

    public void clear() {
        Arrays.fill(direct, EMPTY);
        directCount = 0;
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
