package org.jmclbench.core.timeline;

/**
 * The dataset's odometry and laser events merged by time (ties: odometry first), the order in
 * which the dispatcher releases them. Event k (0..size-1) is the {@link #taskIndex(int)}-th
 * event of task {@link #task(int)}.
 */
public final class Timeline {
    /** Task of an odometry event: a predict job. */
    public static final int PREDICT = 0;
    /** Task of a laser event: an update job. */
    public static final int UPDATE = 1;

    private final double[] time;
    private final byte[] task;
    private final int[] taskIndex;
    private final int predictCount;
    private final int updateCount;

    private Timeline(double[] time, byte[] task, int[] taskIndex, int predictCount, int updateCount) {
        this.time = time;
        this.task = task;
        this.taskIndex = taskIndex;
        this.predictCount = predictCount;
        this.updateCount = updateCount;
    }

    /** Merges two sorted time series: odometry (PREDICT) and laser (UPDATE), odometry first on ties. */
    public static Timeline merge(double[] odoTime, double[] laserTime) {
        int n = odoTime.length + laserTime.length;
        double[] time = new double[n];
        byte[] task = new byte[n];
        int[] taskIndex = new int[n];
        int i = 0;
        int j = 0;
        for (int k = 0; k < n; k++) {
            if (j >= laserTime.length || (i < odoTime.length && odoTime[i] <= laserTime[j])) {
                time[k] = odoTime[i];
                task[k] = PREDICT;
                taskIndex[k] = i++;
            } else {
                time[k] = laserTime[j];
                task[k] = UPDATE;
                taskIndex[k] = j++;
            }
        }
        return new Timeline(time, task, taskIndex, odoTime.length, laserTime.length);
    }

    /** The number of events. */
    public int size() {
        return time.length;
    }

    /** Event k's time from the start of the run (s). */
    public double time(int k) {
        return time[k];
    }

    /** Event k's task: {@link #PREDICT} or {@link #UPDATE}. */
    public int task(int k) {
        return task[k];
    }

    /** Event k's index among the events of its task. */
    public int taskIndex(int k) {
        return taskIndex[k];
    }

    /** The number of odometry (predict) events. */
    public int predictCount() {
        return predictCount;
    }

    /** The number of laser (update) events. */
    public int updateCount() {
        return updateCount;
    }

    /** The number of events of the given task. */
    public int count(int task) {
        return task == PREDICT ? predictCount : updateCount;
    }
}
