package javax.safetycritical;

import javax.realtime.ConfigurationParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.Arguments;

/** Runs the given missions in order, then stops; with {@code repeat}, starts over forever. */
@SCJAllowed
public class LinearMissionSequencer extends MissionSequencer {
    private final Mission[] missions;
    private final boolean repeat;
    private int next;

    /** One mission, named sequencer. */
    @SCJAllowed
    public LinearMissionSequencer(PriorityParameters priority, ScopeParameters storage, ConfigurationParameters config,
            Mission mission, boolean repeat, String name) {
        super(priority, storage, config, name);
        if (mission == null) {
            throw new IllegalArgumentException("mission is null");
        }
        this.missions = new Mission[] {mission};
        this.repeat = repeat;
    }

    /** One mission. */
    @SCJAllowed
    public LinearMissionSequencer(PriorityParameters priority, ScopeParameters storage, ConfigurationParameters config,
            Mission mission, boolean repeat) {
        this(priority, storage, config, mission, repeat, "LinearMS");
    }

    /** Several missions, named sequencer. */
    @SCJAllowed
    public LinearMissionSequencer(PriorityParameters priority, ScopeParameters storage, ConfigurationParameters config,
            Mission[] missions, boolean repeat, String name) {
        super(priority, storage, config, name);
        if (missions == null || missions.length == 0) {
            throw new IllegalArgumentException("no missions");
        }
        this.missions = Arguments.copyWithoutNulls(missions, "a mission is null");
        this.repeat = repeat;
    }

    /** Several missions. */
    @SCJAllowed
    public LinearMissionSequencer(PriorityParameters priority, ScopeParameters storage, ConfigurationParameters config,
            Mission[] missions, boolean repeat) {
        this(priority, storage, config, missions, repeat, "LinearMSs");
    }

    @Override
    @SCJAllowed(Level.SUPPORT)
    protected final Mission getNextMission() {
        if (next >= missions.length) {
            if (!repeat) {
                return null;
            }
            next = 0;
        }
        return missions[next++];
    }
}
