package javax.realtime;

/**
 * The one {@code clone()} of javax.realtime's Cloneable values (times and parameters): a shallow
 * copy, as RTSJ specifies. Package-private, so no public signature changes; the constructor is
 * protected so that serializable subclasses in other packages ({@code ScopeParameters}) can still
 * be deserialized.
 */
abstract class ShallowCloneable implements Cloneable {
    protected ShallowCloneable() {
    }

    @Override
    public Object clone() {
        try {
            return super.clone();
        } catch (CloneNotSupportedException e) {
            throw new InternalError(getClass().getName() + " is Cloneable");
        }
    }
}
