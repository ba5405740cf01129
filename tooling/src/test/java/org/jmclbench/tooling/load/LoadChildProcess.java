package org.jmclbench.tooling.load;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * A stand-in for the runner in {@link CpuLoadTest}: starts CPU hogs with a long time limit,
 * prints {@code PIDS <hog and descendant pids>}, then either waits to be killed
 * ({@code wait}) or crashes with an uncaught exception ({@code crash}).
 */
public final class LoadChildProcess {
    private LoadChildProcess() {
    }

    public static void main(String[] args) throws Exception {
        boolean stressNg = args[1].equals("stress-ng");
        CpuLoad load = CpuLoad.start(2, Duration.ofSeconds(600), stressNg);
        List<Long> pids = new ArrayList<>(load.pids());
        long deadline = System.nanoTime() + 20_000_000_000L;
        if (stressNg) {
            // stress-ng forks its workers after it starts: wait for them so that they are checked too.
            while (System.nanoTime() < deadline && descendants(load).size() < 2) {
                Thread.sleep(50);
            }
        }
        pids.addAll(descendants(load));
        System.out.println("PIDS " + String.join(" ", pids.stream().map(String::valueOf).toList()));
        System.out.flush();
        if (args[0].equals("crash")) {
            throw new IllegalStateException("deliberate crash of the process that owns the load");
        }
        Thread.sleep(600_000);
    }

    private static List<Long> descendants(CpuLoad load) {
        List<Long> out = new ArrayList<>();
        for (long pid : load.pids()) {
            ProcessHandle.of(pid).ifPresent(h -> h.descendants().forEach(d -> out.add(d.pid())));
        }
        return out;
    }
}
