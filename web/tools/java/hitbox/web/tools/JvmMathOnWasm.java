package hitbox.web.tools;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.TreeMap;
import org.teavm.model.BasicBlock;
import org.teavm.model.ClassHolder;
import org.teavm.model.ClassHolderTransformer;
import org.teavm.model.ClassHolderTransformerContext;
import org.teavm.model.Instruction;
import org.teavm.model.MethodHolder;
import org.teavm.model.MethodReference;
import org.teavm.model.ValueType;
import org.teavm.model.Variable;
import org.teavm.model.instructions.InvocationType;
import org.teavm.model.instructions.InvokeInstruction;
import org.teavm.model.instructions.NegateInstruction;
import org.teavm.model.instructions.NumericOperandType;

/**
 * A TeaVM class transformer for the browser build: every call of a Java platform method that
 * TeaVM's class library (0.16.0) lacks ({@code Math.fma}) or answers otherwise than the JVM
 * ({@code Math.hypot}, {@code round}, {@code rint}, {@code IEEEremainder}, {@code toRadians}, {@code scalb}, {@code ulp}, {@code atan2},
 * {@code Random.nextInt(int)}, and {@code StrictMath.sin}/{@code cos}, which it answers from
 * the JavaScript engine) becomes a call of its stand-in in {@code hitbox.web} ({@code ExactFma},
 * {@code JvmMath}, {@code Fdlibm}), whose answers are the JVM's.
 *
 * <p>And every {@code float} or {@code double} negation becomes {@code JvmMath.negate}: TeaVM
 * 0.16.0's WebAssembly GC code generator writes {@code -x} as {@code 0 - x}, which is +0.0 where
 * Java's {@code -(+0.0)} is -0.0 (WasmGCInstructionGenerationVisitor, case NEGATE), and the
 * library's normals carry that sign on.
 *
 * <p>Nothing of the library's own code changes; the JVM build never sees this class.
 */
public final class JvmMathOnWasm implements ClassHolderTransformer {
    private static final ValueType D = ValueType.DOUBLE;
    private static final ValueType F = ValueType.FLOAT;
    private static final ValueType I = ValueType.INTEGER;
    private static final ValueType J = ValueType.LONG;
    private static final ValueType RANDOM = ValueType.object("java.util.Random");

    /** Static calls: the platform's method, and its stand-in with the same parameters. */
    static final Map<MethodReference, MethodReference> STATIC = new LinkedHashMap<>();
    /** Instance calls: the platform's method, and a static stand-in taking the instance first. */
    static final Map<MethodReference, MethodReference> VIRTUAL = new LinkedHashMap<>();

    static {
        STATIC.put(math("fma", D, D, D, D), new MethodReference("hitbox.web.ExactFma", "fma", D, D, D, D));
        STATIC.put(math("hypot", D, D, D), jvm("hypot", D, D, D));
        STATIC.put(math("round", F, I), jvm("round", F, I));
        STATIC.put(math("round", D, J), jvm("round", D, J));
        STATIC.put(math("rint", D, D), jvm("rint", D, D));
        STATIC.put(math("IEEEremainder", D, D, D), jvm("IEEEremainder", D, D, D));
        STATIC.put(math("toRadians", D, D), jvm("toRadians", D, D));
        STATIC.put(math("scalb", D, I, D), jvm("scalb", D, I, D));
        STATIC.put(math("ulp", D, D), jvm("ulp", D, D));
        STATIC.put(math("atan2", D, D, D), new MethodReference("hitbox.internal.Fdlibm", "atan2", D, D, D));
        // The library calls StrictMath.sin/cos (fdlibm on every JVM); TeaVM's would ask the
        // JavaScript engine's Math.sin/cos, which may differ from fdlibm in the last bit.
        STATIC.put(new MethodReference("java.lang.StrictMath", "sin", D, D), new MethodReference("hitbox.internal.Fdlibm", "sin", D, D));
        STATIC.put(new MethodReference("java.lang.StrictMath", "cos", D, D), new MethodReference("hitbox.internal.Fdlibm", "cos", D, D));
        VIRTUAL.put(new MethodReference("java.util.Random", "nextInt", I, I), jvm("nextInt", RANDOM, I, I));
    }

    /** How many calls of each were pointed at a stand-in, for the build's log. */
    static final Map<String, Integer> REPLACED = new TreeMap<>();

    private static MethodReference math(String name, ValueType... signature) {
        return new MethodReference("java.lang.Math", name, signature);
    }

    private static MethodReference jvm(String name, ValueType... signature) {
        return new MethodReference("hitbox.web.JvmMath", name, signature);
    }

    @Override
    public void transformClass(ClassHolder cls, ClassHolderTransformerContext context) {
        // The stand-ins call the platform's methods themselves (JvmMath.hypot calls Math.sqrt).
        boolean standIn = cls.getName().equals("hitbox.web.ExactFma") || cls.getName().equals("hitbox.web.JvmMath")
                || cls.getName().equals("hitbox.internal.Fdlibm");
        for (MethodHolder method : cls.getMethods()) {
            if (method.getProgram() == null) {
                continue;
            }
            for (BasicBlock block : method.getProgram().getBasicBlocks()) {
                for (Instruction insn : block) {
                    if (insn instanceof InvokeInstruction && !standIn) {
                        replace((InvokeInstruction) insn);
                    } else if (insn instanceof NegateInstruction) {
                        negate((NegateInstruction) insn);
                    }
                }
            }
        }
    }

    private static void replace(InvokeInstruction invoke) {
        MethodReference called = invoke.getMethod();
        MethodReference standIn = STATIC.get(called);
        if (standIn != null && invoke.getInstance() == null) {
            invoke.setMethod(standIn);
            count(called);
            return;
        }
        standIn = VIRTUAL.get(called);
        if (standIn != null && invoke.getInstance() != null) {
            Variable[] args = new Variable[invoke.getArguments().size() + 1];
            args[0] = invoke.getInstance();
            for (int i = 1; i < args.length; i++) {
                args[i] = invoke.getArguments().get(i - 1);
            }
            invoke.setInstance(null);
            invoke.setType(InvocationType.SPECIAL);
            invoke.setMethod(standIn);
            invoke.setArguments(args);
            count(called);
        }
    }

    private static void negate(NegateInstruction negate) {
        NumericOperandType type = negate.getOperandType();
        if (type != NumericOperandType.FLOAT && type != NumericOperandType.DOUBLE) {
            return;
        }
        ValueType t = type == NumericOperandType.FLOAT ? F : D;
        InvokeInstruction call = new InvokeInstruction();
        call.setType(InvocationType.SPECIAL);
        call.setMethod(jvm("negate", t, t));
        call.setArguments(negate.getOperand());
        call.setReceiver(negate.getReceiver());
        call.setLocation(negate.getLocation());
        negate.replace(call);
        synchronized (JvmMathOnWasm.class) {
            REPLACED.merge("negation (" + (t == F ? "float" : "double") + ")", 1, Integer::sum);
        }
    }

    private static synchronized void count(MethodReference called) {
        REPLACED.merge(called.getClassName().replace("java.lang.", "").replace("java.util.", "") + "."
                + called.getName() + called.getDescriptor().toString(), 1, Integer::sum);
    }
}
