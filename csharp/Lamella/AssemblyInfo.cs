using System.Reflection;
using System.Runtime.CompilerServices;

[assembly: AssemblyTitle("Lamella")]
[assembly: AssemblyDescription("C# binding of the Lamella C ABI (rectifying strip patterns)")]
[assembly: AssemblyVersion("0.1.0.0")]
// The tests call the raw declarations (every status, mechanical header comparison).
[assembly: InternalsVisibleTo("Lamella.Tests")]
