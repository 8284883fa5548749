/**
 * Hitbox, the collision library: the API package {@code hitbox} only.
 *
 * <p>{@code hitbox.internal} is in the jar but not exported: it is the machinery behind the
 * API and may change in any release. On the class path (the Processing IDE, most builds) this
 * file is ignored and nothing changes; on the module path, {@code requires hitbox;} gives the
 * API and refuses the internals at compile time.
 */
module hitbox {
    exports hitbox;
}
