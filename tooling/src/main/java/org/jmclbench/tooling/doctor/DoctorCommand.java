package org.jmclbench.tooling.doctor;

import java.util.List;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** Checks this machine for real-time measurement, like rtcheck. */
@Command(name = "doctor", mixinStandardHelpOptions = true,
        header = "Checks this machine for real-time measurement.",
        description = {"Checks this machine for real-time measurement (PREEMPT_RT, RT throttling, SCHED_FIFO permission, "
                + "memlock, CPU governor, CPU idle states, isolated CPUs, transparent huge pages, clocksource, virtualisation, memory, "
                + "steal time, cyclictest, the icecap HVM). The same checks are stored with every matrix. Exit code 0 whatever the findings."})
public final class DoctorCommand implements Callable<Integer> {

    @Option(names = "--json", description = "print JSON: [{\"check\",\"status\",\"value\",\"advice\"}]")
    boolean json;

    @Override
    public Integer call() {
        List<DoctorCheck> checks = Doctor.system().run();
        if (json) {
            System.out.println(Doctor.toJson(checks));
            return 0;
        }
        for (DoctorCheck c : checks) {
            System.out.printf("%-4s  %-22s %s%n", c.status(), c.check(), c.value());
            if (!c.advice().isEmpty()) {
                System.out.printf("      %-22s -> %s%n", "", c.advice());
            }
        }
        long warn = checks.stream().filter(c -> c.status().equals("WARN")).count();
        long fail = checks.stream().filter(c -> c.status().equals("FAIL")).count();
        System.out.printf("%d checks: %d passed, %d warnings, %d failed%n", checks.size(), checks.size() - warn - fail, warn, fail);
        return 0;
    }
}
