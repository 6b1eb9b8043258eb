// Developer and CI tool for the member check of the Grasshopper plugin (see csharp/facades/check/README.md).
//   mono MemberTool.exe overrides <plugin.gha>
//       prints, one per line, every SDK method the plugin overrides, as [Assembly]Type::Name(parameters) with Type the
//       nearest SDK class that declares it (the facades, or the real SDK, must be loadable next to the plugin).
//   mono MemberTool.exe verify <assembly.dll> <members.txt>
//       resolves every member of members.txt whose assembly is <assembly.dll>'s (lines "[Asm]Type::Name(params)",
//       text after '#' ignored) in that assembly as the runtime would (the type, then its base types), printing
//       "ok" or "MISSING" per member; exit status 1 when one is missing. Run it against the real RhinoCommon.dll and
//       GH_IO.dll on a developer machine, each in its own process.
//   mono MemberTool.exe describe <assembly.dll>
//       prints every public or protected constructor, method (accessors included), field and enum value of the
//       assembly's public types with its static-ness and return type, sorted: run it on a facade and on the real
//       assembly (two processes: Mono cannot load two assemblies of one name side by side) and compare with `comm -23`
//       to list what the facade declares that the real assembly does not.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;

namespace Lamella.MemberCheck
{
    public static class MemberTool
    {
        private static readonly string[] Sdk = { "Grasshopper", "RhinoCommon", "GH_IO" };
        private const BindingFlags All = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;

        public static int Main(string[] args)
        {
            try
            {
                if (args.Length == 2 && args[0] == "overrides") return Overrides(args[1]);
                if (args.Length == 3 && args[0] == "verify") return Verify(args[1], args[2]);
                if (args.Length == 2 && args[0] == "describe") return Describe(args[1]);
                Console.Error.WriteLine("usage: MemberTool.exe overrides <plugin.gha> | verify <assembly.dll> <members.txt> | describe <assembly.dll>");
                return 2;
            }
            catch (Exception e)
            {
                Console.Error.WriteLine("MemberTool: " + e);
                return 2;
            }
        }

        private static int Overrides(string plugin)
        {
            Assembly assembly = Assembly.LoadFrom(plugin);
            var lines = new SortedSet<string>(StringComparer.Ordinal);
            foreach (Type type in assembly.GetTypes())
            {
                foreach (MethodInfo method in type.GetMethods(All))
                {
                    if (!method.IsVirtual || (method.Attributes & MethodAttributes.NewSlot) != 0) continue;
                    Type sdkType = DeclaringSdkType(type.BaseType, method);
                    if (sdkType != null) lines.Add(Canonical(sdkType, method.Name, method.GetParameters()));
                }
            }
            foreach (string line in lines) Console.WriteLine(line);
            return 0;
        }

        /// <summary>The nearest SDK class from <paramref name="type"/> up that declares a method like <paramref name="method"/>.</summary>
        private static Type DeclaringSdkType(Type type, MethodInfo method)
        {
            Type[] parameters = method.GetParameters().Select(p => p.ParameterType).ToArray();
            for (; type != null; type = type.BaseType)
            {
                if (!Sdk.Contains(type.Assembly.GetName().Name)) continue;
                Type definition = type.IsGenericType ? type.GetGenericTypeDefinition() : type;
                foreach (MethodInfo candidate in definition.GetMethods(All))
                {
                    if (candidate.Name == method.Name && SameParameters(candidate.GetParameters(), parameters, type)) return definition;
                }
            }
            return null;
        }

        private static bool SameParameters(ParameterInfo[] candidate, Type[] wanted, Type constructed)
        {
            if (candidate.Length != wanted.Length) return false;
            for (int i = 0; i < wanted.Length; i++)
            {
                Type c = candidate[i].ParameterType;
                if (c.IsGenericParameter && constructed.IsGenericType) c = constructed.GetGenericArguments()[c.GenericParameterPosition];
                if (c != wanted[i]) return false;
            }
            return true;
        }

        private static string Canonical(Type owner, string name, ParameterInfo[] parameters) =>
            TypeName(owner) + "::" + name + "(" + string.Join(", ", parameters.Select(p => TypeName(p.ParameterType))) + ")";

        /// <summary>A type as monodis writes it in signatures, without the class/valuetype keywords.</summary>
        public static string TypeName(Type t)
        {
            if (t.IsByRef) return TypeName(t.GetElementType()) + "&";
            if (t.IsArray) return TypeName(t.GetElementType()) + "[]";
            if (t.IsGenericParameter) return (t.DeclaringMethod != null ? "!!" : "!") + t.GenericParameterPosition;
            string primitive;
            if (Primitives.TryGetValue(t.FullName ?? "", out primitive)) return primitive;
            Type definition = t.IsGenericType ? t.GetGenericTypeDefinition() : t;
            string name = definition.IsNested ? TypeName(definition.DeclaringType) + "/" + definition.Name : "[" + definition.Assembly.GetName().Name + "]" + definition.FullName;
            if (t.IsGenericType && !t.IsGenericTypeDefinition) name += "<" + string.Join(", ", t.GetGenericArguments().Select(TypeName)) + ">";
            return name;
        }

        private static readonly Dictionary<string, string> Primitives = new Dictionary<string, string>
        {
            { "System.Void", "void" }, { "System.Boolean", "bool" }, { "System.Char", "char" }, { "System.SByte", "int8" },
            { "System.Byte", "unsigned int8" }, { "System.Int16", "int16" }, { "System.UInt16", "unsigned int16" }, { "System.Int32", "int32" },
            { "System.UInt32", "unsigned int32" }, { "System.Int64", "int64" }, { "System.UInt64", "unsigned int64" }, { "System.Single", "float32" },
            { "System.Double", "float64" }, { "System.String", "string" }, { "System.Object", "object" }, { "System.IntPtr", "native int" },
        };

        private static int Verify(string assemblyPath, string membersPath)
        {
            Assembly assembly = Assembly.LoadFrom(assemblyPath);
            string prefix = "[" + assembly.GetName().Name + "]";
            int missing = 0, checkedCount = 0;
            foreach (string raw in File.ReadAllLines(membersPath))
            {
                string line = raw.Split('#')[0].Trim();
                if (!line.StartsWith(prefix, StringComparison.Ordinal) || !line.Contains("::")) continue;
                checkedCount++;
                bool found = Resolve(assembly, line);
                if (!found) missing++;
                Console.WriteLine((found ? "ok       " : "MISSING  ") + line);
            }
            Console.WriteLine(checkedCount + " members of " + assembly.GetName().Name + " " + assembly.GetName().Version + " checked, " + missing + " missing");
            return missing == 0 ? 0 : 1;
        }

        private static int Describe(string assemblyPath)
        {
            Assembly assembly = Assembly.LoadFrom(assemblyPath);
            var lines = new SortedSet<string>(StringComparer.Ordinal);
            foreach (Type type in assembly.GetTypes())
            {
                if (!(type.IsPublic || type.IsNestedPublic)) continue;
                string owner = TypeName(type);
                lines.Add("type " + owner + (type.BaseType != null ? " : " + TypeName(type.BaseType) : ""));
                foreach (ConstructorInfo c in type.GetConstructors(All))
                {
                    if (Visible(c)) lines.Add((c.IsStatic ? "static " : "") + owner + "::.ctor(" + Parameters(c) + ")");
                }
                foreach (MethodInfo m in type.GetMethods(All))
                {
                    if (Visible(m)) lines.Add((m.IsStatic ? "static " : "") + (m.IsAbstract ? "abstract " : m.IsVirtual && !m.IsFinal ? "virtual " : "") + TypeName(m.ReturnType) + " " + owner + "::" + m.Name + "(" + Parameters(m) + ")");
                }
                foreach (FieldInfo f in type.GetFields(All))
                {
                    if (!(f.IsPublic || f.IsFamily || f.IsFamilyOrAssembly)) continue;
                    lines.Add(f.IsLiteral ? "literal " + owner + "::" + f.Name + " = " + Convert.ToString(f.GetRawConstantValue(), System.Globalization.CultureInfo.InvariantCulture)
                        : (f.IsStatic ? "static " : "") + "field " + TypeName(f.FieldType) + " " + owner + "::" + f.Name);
                }
            }
            foreach (string line in lines) Console.WriteLine(line);
            return 0;
        }

        private static bool Visible(MethodBase m) => m.IsPublic || m.IsFamily || m.IsFamilyOrAssembly;

        private static string Parameters(MethodBase m) => string.Join(", ", m.GetParameters().Select(p => TypeName(p.ParameterType)));

        private static bool Resolve(Assembly assembly, string line)
        {
            int split = line.IndexOf("::", StringComparison.Ordinal);
            string typeName = line.Substring(0, split).Substring(line.IndexOf(']') + 1).Replace('/', '+');
            string member = line.Substring(split + 2);
            Type type = assembly.GetType(typeName, false);
            if (type == null) return false;
            int paren = member.IndexOf('(');
            if (paren < 0) return Hierarchy(type).Any(t => t.GetField(member, All) != null);
            string name = member.Substring(0, paren);
            string parameters = member.Substring(paren + 1, member.Length - paren - 2);
            IEnumerable<MethodBase> candidates = name == ".ctor"
                ? type.GetConstructors(All).Cast<MethodBase>()
                : Hierarchy(type).SelectMany(t => t.GetMethods(All)).Where(m => m.Name == name).Cast<MethodBase>();
            return candidates.Any(m => string.Join(", ", m.GetParameters().Select(p => TypeName(p.ParameterType))) == parameters);
        }

        private static IEnumerable<Type> Hierarchy(Type type)
        {
            for (; type != null; type = type.BaseType) yield return type;
        }
    }
}
