package org.jmclbench.tooling.attribution;

/**
 * One reason a job missed or was late.
 *
 * @param kind   {@code gc}, {@code safepoint}, {@code jit}, {@code deopt}, {@code classload},
 *               {@code lock}, {@code queued}, {@code os}, {@code preemption}, {@code compute},
 *               {@code overlap} or {@code unknown} (docs/FORMATS.md section 5)
 * @param ns     how much of the job's window it accounts for, in ns (for {@code compute}: the
 *               job's CPU time; {@code os}: the start delay not explained otherwise)
 * @param detail what exactly: collector and pause, methods, the blocking job
 */
public record Cause(String kind, long ns, String detail) {
}
