package org.jmclbench.tooling.doctor;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;

/** Checks what decides real-time results on this machine. */
@Command(name = "doctor", mixinStandardHelpOptions = true, description = "Checks what decides real-time results on this machine.")
public final class DoctorCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        System.err.println("jmclbench: doctor: not built yet");
        return 1;
    }
}
