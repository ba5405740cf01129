package org.jmclbench.tooling.doctor;

/**
 * One fact about the machine's fitness for real-time measurement.
 *
 * @param check  short name ({@code preempt-rt}, {@code rt-throttling}, ...)
 * @param status PASS, WARN or FAIL
 * @param value  what was found
 * @param advice what to do about it (empty when PASS)
 */
public record DoctorCheck(String check, String status, String value, String advice) {
    public static DoctorCheck pass(String check, String value) {
        return new DoctorCheck(check, "PASS", value, "");
    }

    public static DoctorCheck warn(String check, String value, String advice) {
        return new DoctorCheck(check, "WARN", value, advice);
    }

    public static DoctorCheck fail(String check, String value, String advice) {
        return new DoctorCheck(check, "FAIL", value, advice);
    }
}
