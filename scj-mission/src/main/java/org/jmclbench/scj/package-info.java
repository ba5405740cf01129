/**
 * Monte-Carlo Localization as a Safety-Critical Java Level 1 application (SPEC section 12).
 *
 * <p>Read top-down: {@link org.jmclbench.scj.MclSafelet} (immortal: the
 * {@link org.jmclbench.scj.ImmortalEntry} with the sensor log, schedule and job records) ->
 * a {@code LinearMissionSequencer} -> {@link org.jmclbench.scj.MclMission} (mission memory: the
 * localizer, the {@link org.jmclbench.scj.Robot}, the {@link org.jmclbench.scj.JobGate}) -> the
 * handlers {@link org.jmclbench.scj.PredictHandler} (periodic), {@link org.jmclbench.scj.LaserSensor}
 * (one-shot, rearmed at each laser time) and {@link org.jmclbench.scj.UpdateHandler} (aperiodic,
 * released by the sensor). Each release runs in its handler's private memory.
 *
 * <p>Seams, so that another VM or a verifier can plug in without touching the mission:
 * <ul>
 *   <li>{@link org.jmclbench.scj.MissionInput}: the data in (sensor log, field, start pose);</li>
 *   <li>{@link org.jmclbench.scj.MissionOutput}: the job records out, once, after the mission;</li>
 *   <li>{@link org.jmclbench.scj.MissionConfiguration}: the parameters (filter, policy, time scale,
 *       area sizes) and the factories {@code newLocalizer}, {@code newRobot}, {@code newGate}
 *       that a test subclass overrides to seed a bug;</li>
 *   <li>sizes: particles and the abort poll interval through {@code MclConfig}, the events
 *       through the input, so a model checker can run the real mission on a few of each.</li>
 * </ul>
 * Nothing is static and mutable: two missions in one process share no state.
 */
package org.jmclbench.scj;
