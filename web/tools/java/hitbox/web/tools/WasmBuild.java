package hitbox.web.tools;

import java.io.File;
import org.teavm.tooling.ConsoleTeaVMToolLog;
import org.teavm.tooling.TeaVMProblemRenderer;
import org.teavm.tooling.TeaVMTargetType;
import org.teavm.tooling.TeaVMTool;
import org.teavm.vm.TeaVMOptimizationLevel;

/**
 * The browser build's compiler run (gradle/web.gradle's task webWasm): TeaVM compiles the
 * entry class and what it reaches to WebAssembly GC, with {@link JvmMathOnWasm} installed.
 *
 * <p>Arguments: the entry class, the output folder, the output file name.
 */
public final class WasmBuild {
    private WasmBuild() {
    }

    public static void main(String[] args) throws Exception {
        TeaVMTool tool = new TeaVMTool();
        tool.setTargetType(TeaVMTargetType.WEBASSEMBLY_GC);
        tool.setMainClass(args[0]);
        tool.setTargetDirectory(new File(args[1]));
        tool.setTargetFileName(args[2]);
        tool.setObfuscated(true);
        // Strict: null dereferences, array bounds and casts throw as on the JVM, not trap.
        tool.setStrict(true);
        tool.setOptimizationLevel(TeaVMOptimizationLevel.ADVANCED);
        tool.setClassLoader(WasmBuild.class.getClassLoader());
        tool.getTransformers().add(JvmMathOnWasm.class.getName());
        ConsoleTeaVMToolLog log = new ConsoleTeaVMToolLog(false);
        tool.setLog(log);
        tool.generate();
        TeaVMProblemRenderer.describeProblems(tool.getDependencyInfo().getCallGraph(), tool.getProblemProvider(), log);
        if (!tool.getProblemProvider().getSevereProblems().isEmpty()) {
            throw new IllegalStateException("TeaVM could not compile the browser build: see the problems above");
        }
        System.out.println("Calls pointed at their JVM-exact stand-ins: " + JvmMathOnWasm.REPLACED);
    }
}
