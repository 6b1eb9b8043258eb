using System.Reflection;

[assembly: AssemblyTitle("Lamella.Grasshopper")]
[assembly: AssemblyDescription("Grasshopper components of Lamella (rectifying strip patterns)")]
[assembly: AssemblyVersion("0.1.0.0")]
// The package version: equal to `version` in manifest.yml (scripts/test-csharp.sh checks it).
[assembly: AssemblyInformationalVersion("0.1.0")]
