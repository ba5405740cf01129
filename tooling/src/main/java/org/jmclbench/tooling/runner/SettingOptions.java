package org.jmclbench.tooling.runner;

import java.util.ArrayList;
import java.util.List;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * The matrix settings ({@link MatrixOptions#SETTINGS}) as command-line options: a command that
 * takes some of them adds them with {@link #add} (from its picocli model transformer) and hands
 * what was given to a {@link MatrixSpec} with {@link #apply}, so each setting's option, label,
 * help and parsing are written once, for the matrix file and every command alike.
 */
final class SettingOptions {
    private SettingOptions() {
    }

    /**
     * Adds the options of the settings {@code keys} to {@code command}, in the settings' order, after
     * its first {@code position} options (the others, --help and --version among them, after them).
     */
    static CommandSpec add(CommandSpec command, int position, List<String> keys) {
        List<OptionSpec> after = new ArrayList<>(command.options().subList(position, command.options().size()));
        after.forEach(command::remove);
        for (MatrixOptions.Setting s : MatrixOptions.SETTINGS) {
            if (keys.contains(s.key())) {
                OptionSpec.Builder b = OptionSpec.builder("--" + s.key()).paramLabel(s.label()).description(s.description())
                        .userObject(s);
                command.addOption(s.list() ? b.type(List.class).auxiliaryTypes(String.class).build()
                        : b.type(String.class).build());
            }
        }
        after.forEach(command::addOption);
        return command;
    }

    /**
     * Applies the settings given on {@code command}'s line to {@code spec}, in the order of its options:
     * a list given replaces the list a matrix file set, a value replaces its value.
     */
    static void apply(CommandSpec command, MatrixSpec spec) {
        for (OptionSpec option : command.options()) {
            if (option.userObject() instanceof MatrixOptions.Setting s) {
                if (s.list()) {
                    List<String> values = option.getValue();
                    list(spec, s.key(), values == null ? List.of() : values);
                } else {
                    one(spec, s.key(), option.getValue());
                }
            }
        }
    }

    /** A list setting: replaces what a matrix file set, when given. */
    static void list(MatrixSpec spec, String key, List<String> values) {
        if (!values.isEmpty()) {
            MatrixOptions.clear(spec, key);
            values.forEach(v -> MatrixOptions.apply(spec, key, v, "--" + key));
        }
    }

    /** A one-value setting, when given. */
    static void one(MatrixSpec spec, String key, String value) {
        if (value != null) {
            MatrixOptions.apply(spec, key, value, "--" + key);
        }
    }
}
