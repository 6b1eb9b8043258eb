using System.Reflection;

[assembly: AssemblyTitle("Lamella.Grasshopper")]
[assembly: AssemblyDescription("Grasshopper components of Lamella (rectifying strip patterns)")]
[assembly: AssemblyVersion("0.1.0.0")]
