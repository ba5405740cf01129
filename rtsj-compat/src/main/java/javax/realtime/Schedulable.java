package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** Something the scheduler runs: an event handler or a thread. */
@SCJAllowed
public interface Schedulable extends Runnable {
}
