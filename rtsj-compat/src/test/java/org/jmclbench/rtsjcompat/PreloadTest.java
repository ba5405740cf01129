package org.jmclbench.rtsjcompat;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Arrays;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The preload list names exactly this layer's top-level runtime classes. */
class PreloadTest {
    @Test
    void listsEveryTopLevelClassOfTheLayer() throws IOException {
        Path root = Paths.get("target/classes");
        Set<String> found;
        try (Stream<Path> s = Files.walk(root)) {
            found = s.map(p -> root.relativize(p).toString())
                    .filter(n -> n.endsWith(".class") && !n.contains("$") && !n.contains("annotate"))
                    .map(n -> n.substring(0, n.length() - ".class".length()).replace('/', '.'))
                    .filter(n -> !n.endsWith("ThreadMxAllocationMeter"))
                    .collect(Collectors.toCollection(TreeSet::new));
        }
        assertEquals(found, new TreeSet<>(Arrays.asList(Preload.CLASSES)));
        Preload.run();
    }
}
