using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;

// Checks that a DLL carries its portable PDB embedded, that the PDB names every C# source file of the project and that it
// embeds each of its documents, so a debugger steps into the library from the package alone.
// Usage: PdbCheck <file.dll> <project folder> <mapped prefix> (the prefix is what PathMap writes for the project folder,
// e.g. /_/src/AcDream.Core/). Prints one line; exit 1 on failure.
if (args.Length != 3)
{
    Console.WriteLine("usage: PdbCheck <file.dll> <project folder> <mapped prefix>");
    return 2;
}

var embeddedSource = new Guid("0E8A571B-6926-466E-B4AD-8AB04611F5FE");
using FileStream stream = File.OpenRead(args[0]);
using var pe = new PEReader(stream);
DebugDirectoryEntry embeddedPdb = pe.ReadDebugDirectory().FirstOrDefault(e => e.Type == DebugDirectoryEntryType.EmbeddedPortablePdb);
if (embeddedPdb.DataSize == 0)
{
    Console.WriteLine("PDB check FAILED: the DLL has no embedded portable PDB");
    return 1;
}

using MetadataReaderProvider provider = pe.ReadEmbeddedPortablePdbDebugDirectoryData(embeddedPdb);
MetadataReader pdb = provider.GetMetadataReader();

var documents = new Dictionary<string, DocumentHandle>(StringComparer.Ordinal);
foreach (DocumentHandle h in pdb.Documents)
{
    documents[pdb.GetString(pdb.GetDocument(h).Name)] = h;
}

var embedded = new HashSet<DocumentHandle>();
foreach (CustomDebugInformationHandle h in pdb.CustomDebugInformation)
{
    CustomDebugInformation info = pdb.GetCustomDebugInformation(h);
    if (info.Parent.Kind == HandleKind.Document && pdb.GetGuid(info.Kind) == embeddedSource)
    {
        embedded.Add((DocumentHandle)info.Parent);
    }
}

string root = Path.GetFullPath(args[1]);
string prefix = args[2];
var sources = Directory.EnumerateFiles(root, "*.cs", SearchOption.AllDirectories)
    .Select(f => Path.GetRelativePath(root, f).Replace('\\', '/'))
    .Where(r => !r.StartsWith("bin/", StringComparison.Ordinal) && !r.StartsWith("obj/", StringComparison.Ordinal))
    .Select(r => prefix + r)
    .ToList();

var missing = sources.Where(s => !documents.ContainsKey(s)).ToList();
var notEmbedded = documents.Where(d => !embedded.Contains(d.Value)).Select(d => d.Key).ToList();
var unmapped = documents.Keys.Where(d => !d.StartsWith("/_/", StringComparison.Ordinal)).ToList();
if (unmapped.Count > 0)
{
    Console.WriteLine($"PDB check FAILED: {unmapped.Count} documents keep a build-machine path (PathMap gives /_/), e.g. {unmapped[0]}");
    return 1;
}

if (missing.Count > 0)
{
    Console.WriteLine($"PDB check FAILED: {missing.Count} source files are not documents of the PDB, e.g. {missing[0]}");
    return 1;
}

if (notEmbedded.Count > 0)
{
    Console.WriteLine($"PDB check FAILED: {notEmbedded.Count} documents do not embed their source, e.g. {notEmbedded[0]}");
    return 1;
}

Console.WriteLine($"PDB ok: embedded in the DLL, {documents.Count} documents, every one embedded and under /_/; all {sources.Count} source files of the project among them");
return 0;
