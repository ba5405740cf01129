package org.jmclbench.verification.bytecode;

import org.objectweb.asm.ClassReader;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.MethodNode;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Enumeration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;

/**
 * The project's classes read with ASM (class folders and jars), indexed by internal name, with
 * the method resolution a call-graph walk needs: a method in a class or its superclasses, and
 * every override of it in the pool (class hierarchy analysis).
 */
public final class ClassPool {
    private final Map<String, ClassNode> classes = new LinkedHashMap<>();

    /** Reads every class under each folder or in each jar. */
    public static ClassPool of(Collection<Path> entries) throws IOException {
        ClassPool pool = new ClassPool();
        for (Path e : entries) {
            if (Files.isDirectory(e)) {
                try (Stream<Path> files = Files.walk(e)) {
                    for (Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".class"))::iterator) {
                        try (InputStream in = Files.newInputStream(f)) {
                            pool.add(in);
                        }
                    }
                }
            } else if (e.toString().endsWith(".jar") && Files.isRegularFile(e)) {
                try (JarFile jar = new JarFile(e.toFile())) {
                    Enumeration<JarEntry> it = jar.entries();
                    while (it.hasMoreElements()) {
                        JarEntry je = it.nextElement();
                        if (je.getName().endsWith(".class") && !je.getName().startsWith("META-INF/")) {
                            try (InputStream in = jar.getInputStream(je)) {
                                pool.add(in);
                            }
                        }
                    }
                }
            }
        }
        return pool;
    }

    private void add(InputStream in) throws IOException {
        ClassNode cn = new ClassNode();
        new ClassReader(in).accept(cn, 0);
        classes.putIfAbsent(cn.name, cn);
    }

    /** The class with this internal name, or null when it is not one of the project's. */
    public ClassNode get(String internalName) {
        return classes.get(internalName);
    }

    public Collection<ClassNode> all() {
        return classes.values();
    }

    /** The method as the JVM would find it from {@code owner}: there or in a superclass or interface. */
    public Owned resolve(String owner, String name, String desc) {
        for (ClassNode c = get(owner); c != null; c = c.superName == null ? null : get(c.superName)) {
            MethodNode m = find(c, name, desc);
            if (m != null) {
                return new Owned(c, m);
            }
            for (String i : c.interfaces) {
                Owned d = resolve(i, name, desc);
                if (d != null && (d.method().access & org.objectweb.asm.Opcodes.ACC_ABSTRACT) == 0) {
                    return d;
                }
            }
        }
        return null;
    }

    /** Every concrete method of the pool that a virtual call of owner.name desc may run. */
    public List<Owned> implementations(String owner, String name, String desc) {
        List<Owned> out = new ArrayList<>();
        Owned r = resolve(owner, name, desc);
        if (r != null) {
            out.add(r);
        }
        for (ClassNode c : classes.values()) {
            if (!c.name.equals(owner) && isSubtype(c.name, owner)) {
                MethodNode m = find(c, name, desc);
                if (m != null && (m.access & org.objectweb.asm.Opcodes.ACC_ABSTRACT) == 0) {
                    out.add(new Owned(c, m));
                }
            }
        }
        return out;
    }

    /** True when {@code sub} is {@code sup} or extends or implements it, as far as the pool knows. */
    public boolean isSubtype(String sub, String sup) {
        if (sub.equals(sup)) {
            return true;
        }
        ClassNode c = get(sub);
        if (c == null) {
            return false;
        }
        if (c.superName != null && isSubtype(c.superName, sup)) {
            return true;
        }
        for (String i : c.interfaces) {
            if (isSubtype(i, sup)) {
                return true;
            }
        }
        return false;
    }

    private static MethodNode find(ClassNode c, String name, String desc) {
        for (MethodNode m : c.methods) {
            if (m.name.equals(name) && m.desc.equals(desc)) {
                return m;
            }
        }
        return null;
    }

    /** A method with the class that declares it. */
    public record Owned(ClassNode owner, MethodNode method) {
        public String key() {
            return owner.name + "." + method.name + method.desc;
        }
    }
}
