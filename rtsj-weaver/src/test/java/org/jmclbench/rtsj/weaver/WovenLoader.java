package org.jmclbench.rtsj.weaver;

import java.io.IOException;
import java.io.InputStream;

/** Loads the sample classes woven (child first); everything else from the parent. */
final class WovenLoader extends ClassLoader {
    private final Weaver weaver;
    private final String prefix;
    int deliveryPoints;

    WovenLoader(Weaver weaver, Class<?> sample) {
        super(sample.getClassLoader());
        this.weaver = weaver;
        this.prefix = sample.getName();
    }

    @Override
    protected synchronized Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
        if (!name.equals(prefix) && !name.startsWith(prefix + "$")) {
            return super.loadClass(name, resolve);
        }
        Class<?> c = findLoadedClass(name);
        if (c == null) {
            byte[] b = weave(original(name));
            c = defineClass(name, b, 0, b.length);
        }
        if (resolve) {
            resolveClass(c);
        }
        return c;
    }

    private byte[] weave(byte[] in) {
        Weaver.Result r = weaver.weave(in);
        deliveryPoints += r.deliveryPoints;
        return r.bytes;
    }

    static byte[] original(String name) throws ClassNotFoundException {
        try (InputStream in = WovenLoader.class.getClassLoader().getResourceAsStream(name.replace('.', '/') + ".class")) {
            if (in == null) {
                throw new ClassNotFoundException(name);
            }
            return in.readAllBytes();
        } catch (IOException e) {
            throw new ClassNotFoundException(name, e);
        }
    }
}
