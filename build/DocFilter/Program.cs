using System;
using System.Collections.Generic;
using System.Collections.Immutable;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;
using System.Text;
using System.Xml;
using System.Xml.Linq;

namespace AcDream.Build.DocFilter;

/// <summary>
/// Usage: <c>dotnet DocFilter.dll &lt;assembly.dll&gt; &lt;documentation.xml&gt;</c>. Rewrites the XML documentation file in
/// place keeping only the public surface: the <c>T:</c> entries of externally visible types and the members of those types
/// whose accessibility is public, protected or protected internal. Everything else the compiler wrote (private and internal
/// members, members of internal types, explicit interface implementations) is dropped. Every ID in the XML must name a
/// member of the assembly (a guard against a wrong ID computation silently dropping documentation). The file is written only
/// when its content changes, so a rerun over an already filtered file leaves it untouched.
/// </summary>
internal static class Program
{
    private static int Main(string[] args)
    {
        if (args.Length != 2)
        {
            Console.Error.WriteLine("usage: DocFilter <assembly.dll> <documentation.xml>");
            return 2;
        }

        string dllPath = args[0];
        string xmlPath = args[1];
        (HashSet<string> visible, HashSet<string> all) = DocIds.Compute(dllPath);

        XDocument doc = XDocument.Load(xmlPath, LoadOptions.PreserveWhitespace);
        XElement? membersElement = doc.Root?.Element("members");
        if (membersElement is null)
        {
            Console.Error.WriteLine($"DocFilter: error: {xmlPath} has no <members> element");
            return 1;
        }

        List<XElement> members = membersElement.Elements("member").ToList();
        var unknown = new List<string>();
        int kept = 0;
        foreach (XElement member in members)
        {
            string id = (string?)member.Attribute("name") ?? string.Empty;
            if (visible.Contains(id))
            {
                kept++;
                continue;
            }

            if (!all.Contains(id))
            {
                unknown.Add(id);
            }

            // Drop the member and the indentation before it.
            if (member.PreviousNode is XText ws && string.IsNullOrWhiteSpace(ws.Value))
            {
                ws.Remove();
            }

            member.Remove();
        }

        if (unknown.Count > 0)
        {
            foreach (string id in unknown)
            {
                Console.Error.WriteLine($"DocFilter: error: documentation ID '{id}' names no member of {Path.GetFileName(dllPath)}");
            }

            return 1;
        }

        var settings = new XmlWriterSettings { Encoding = new UTF8Encoding(false), Indent = false };
        byte[] newContent;
        using (var stream = new MemoryStream())
        {
            using (var writer = XmlWriter.Create(stream, settings))
            {
                doc.Save(writer);
            }

            newContent = stream.ToArray();
        }

        byte[] oldContent = File.ReadAllBytes(xmlPath);
        if (!oldContent.AsSpan().SequenceEqual(newContent))
        {
            File.WriteAllBytes(xmlPath, newContent);
        }

        Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"DocFilter: {Path.GetFileName(xmlPath)}: kept {kept} of {members.Count} members (the public surface)"));
        return 0;
    }
}

/// <summary>Documentation-comment IDs (ECMA-334 annex D, as Roslyn writes them) of an assembly's types and members.</summary>
internal static class DocIds
{
    /// <summary>The IDs of the visible surface, and of every type and member (visible or not).</summary>
    public static (HashSet<string> Visible, HashSet<string> All) Compute(string dllPath)
    {
        using FileStream stream = File.OpenRead(dllPath);
        using var pe = new PEReader(stream);
        MetadataReader md = pe.GetMetadataReader();
        var provider = new SignatureTypeProvider(md);
        var visible = new HashSet<string>(StringComparer.Ordinal);
        var all = new HashSet<string>(StringComparer.Ordinal);

        foreach (TypeDefinitionHandle th in md.TypeDefinitions)
        {
            TypeDefinition type = md.GetTypeDefinition(th);
            string typeName = TypeDefinitionName(md, th);
            bool typeVisible = IsTypeVisible(md, th);
            Add("T:" + typeName, typeVisible);

            foreach (FieldDefinitionHandle fh in type.GetFields())
            {
                FieldDefinition field = md.GetFieldDefinition(fh);
                Add($"F:{typeName}.{MemberName(md.GetString(field.Name))}", typeVisible && IsVisible((MethodAttributes)(int)(field.Attributes & FieldAttributes.FieldAccessMask)));
            }

            foreach (MethodDefinitionHandle mh in type.GetMethods())
            {
                MethodDefinition method = md.GetMethodDefinition(mh);
                Add(MethodId(md, provider, typeName, method), typeVisible && IsVisible(method.Attributes));
            }

            foreach (PropertyDefinitionHandle ph in type.GetProperties())
            {
                PropertyDefinition property = md.GetPropertyDefinition(ph);
                MethodSignature<string> sig = property.DecodeSignature(provider, null);
                PropertyAccessors accessors = property.GetAccessors();
                bool memberVisible = IsAccessorVisible(md, accessors.Getter) || IsAccessorVisible(md, accessors.Setter)
                    || accessors.Others.Any(a => IsAccessorVisible(md, a));
                Add($"P:{typeName}.{MemberName(md.GetString(property.Name))}{Parameters(sig.ParameterTypes)}", typeVisible && memberVisible);
            }

            foreach (EventDefinitionHandle eh in type.GetEvents())
            {
                EventDefinition ev = md.GetEventDefinition(eh);
                EventAccessors accessors = ev.GetAccessors();
                bool memberVisible = IsAccessorVisible(md, accessors.Adder) || IsAccessorVisible(md, accessors.Remover)
                    || IsAccessorVisible(md, accessors.Raiser);
                Add($"E:{typeName}.{MemberName(md.GetString(ev.Name))}", typeVisible && memberVisible);
            }
        }

        return (visible, all);

        void Add(string id, bool isVisible)
        {
            all.Add(id);
            if (isVisible)
            {
                visible.Add(id);
            }
        }
    }

    private static string MethodId(MetadataReader md, SignatureTypeProvider provider, string typeName, MethodDefinition method)
    {
        string name = MemberName(md.GetString(method.Name));
        MethodSignature<string> sig = method.DecodeSignature(provider, null);
        var id = new StringBuilder("M:").Append(typeName).Append('.').Append(name);
        if (sig.GenericParameterCount > 0)
        {
            id.Append("``").Append(sig.GenericParameterCount.ToString(CultureInfo.InvariantCulture));
        }

        id.Append(Parameters(sig.ParameterTypes));
        if (name is "op_Implicit" or "op_Explicit")
        {
            id.Append('~').Append(sig.ReturnType);
        }

        return id.ToString();
    }

    private static string Parameters(ImmutableArray<string> parameters) =>
        parameters.IsEmpty ? string.Empty : "(" + string.Join(",", parameters) + ")";

    /// <summary>Member names as IDs spell them: <c>.ctor</c> → <c>#ctor</c>, and an explicit implementation's dots → <c>#</c>.</summary>
    private static string MemberName(string name) => name.Replace('.', '#');

    private static bool IsAccessorVisible(MetadataReader md, MethodDefinitionHandle handle) =>
        !handle.IsNil && IsVisible(md.GetMethodDefinition(handle).Attributes);

    /// <summary>Public, protected or protected internal (field access flags have the same values as method access flags).</summary>
    private static bool IsVisible(MethodAttributes attributes) =>
        (attributes & MethodAttributes.MemberAccessMask) is MethodAttributes.Public or MethodAttributes.Family or MethodAttributes.FamORAssem;

    private static bool IsTypeVisible(MetadataReader md, TypeDefinitionHandle handle)
    {
        TypeDefinition type = md.GetTypeDefinition(handle);
        switch (type.Attributes & TypeAttributes.VisibilityMask)
        {
            case TypeAttributes.Public:
                return true;
            case TypeAttributes.NestedPublic:
            case TypeAttributes.NestedFamily:
            case TypeAttributes.NestedFamORAssem:
                return IsTypeVisible(md, type.GetDeclaringType());
            default:
                return false;
        }
    }

    /// <summary>A type's name in a <c>T:</c> ID and as the type part of a member's ID (generic arity kept as <c>`n</c>).</summary>
    private static string TypeDefinitionName(MetadataReader md, TypeDefinitionHandle handle)
    {
        TypeDefinition type = md.GetTypeDefinition(handle);
        string name = md.GetString(type.Name);
        TypeDefinitionHandle declaring = type.GetDeclaringType();
        if (!declaring.IsNil)
        {
            return TypeDefinitionName(md, declaring) + "." + name;
        }

        string ns = md.GetString(type.Namespace);
        return ns.Length == 0 ? name : ns + "." + name;
    }

    /// <summary>
    /// Type strings in a signature: primitives as <c>System.Int32</c>, nested types with <c>.</c>, generic instantiations
    /// as <c>Name{A,B}</c>, type parameters <c>`n</c>, method type parameters <c>``n</c>, arrays <c>[]</c> or
    /// <c>[0:,0:]</c>, by-ref <c>@</c>, pointers <c>*</c>; custom modifiers are not part of an ID.
    /// </summary>
    private sealed class SignatureTypeProvider(MetadataReader md) : ISignatureTypeProvider<string, object?>
    {
        private readonly Dictionary<string, int> nestedDepth = BuildNestingDepths(md);

        public string GetPrimitiveType(PrimitiveTypeCode typeCode) => "System." + typeCode.ToString();

        public string GetTypeFromDefinition(MetadataReader reader, TypeDefinitionHandle handle, byte rawTypeKind) =>
            TypeDefinitionName(reader, handle);

        public string GetTypeFromReference(MetadataReader reader, TypeReferenceHandle handle, byte rawTypeKind) =>
            TypeReferenceName(reader, handle);

        public string GetTypeFromSpecification(MetadataReader reader, object? genericContext, TypeSpecificationHandle handle, byte rawTypeKind) =>
            reader.GetTypeSpecification(handle).DecodeSignature(this, genericContext);

        public string GetSZArrayType(string elementType) => elementType + "[]";

        public string GetArrayType(string elementType, ArrayShape shape)
        {
            var dims = new string[shape.Rank];
            for (int i = 0; i < shape.Rank; i++)
            {
                string lower = i < shape.LowerBounds.Length ? shape.LowerBounds[i].ToString(CultureInfo.InvariantCulture) : "0";
                string size = i < shape.Sizes.Length ? shape.Sizes[i].ToString(CultureInfo.InvariantCulture) : string.Empty;
                dims[i] = lower + ":" + size;
            }

            return elementType + "[" + string.Join(",", dims) + "]";
        }

        public string GetByReferenceType(string elementType) => elementType + "@";

        public string GetPointerType(string elementType) => elementType + "*";

        public string GetPinnedType(string elementType) => elementType;

        public string GetModifiedType(string modifier, string unmodifiedType, bool isRequired) => unmodifiedType;

        public string GetGenericTypeParameter(object? genericContext, int index) => "`" + index.ToString(CultureInfo.InvariantCulture);

        public string GetGenericMethodParameter(object? genericContext, int index) => "``" + index.ToString(CultureInfo.InvariantCulture);

        public string GetFunctionPointerType(MethodSignature<string> signature) =>
            "=FUNC:" + signature.ReturnType + Parameters(signature.ParameterTypes);

        public string GetGenericInstantiation(string genericType, ImmutableArray<string> typeArguments)
        {
            // genericType is the dotted name with each level's `n; hand each level its own n arguments.
            string[] levels = SplitLevels(genericType, out string prefix);
            var result = new StringBuilder(prefix);
            int next = 0;
            for (int i = 0; i < levels.Length; i++)
            {
                if (i > 0)
                {
                    result.Append('.');
                }

                string level = levels[i];
                int tick = level.LastIndexOf('`');
                if (tick < 0)
                {
                    result.Append(level);
                    continue;
                }

                int arity = int.Parse(level.AsSpan(tick + 1), NumberStyles.None, CultureInfo.InvariantCulture);
                result.Append(level, 0, tick).Append('{');
                for (int a = 0; a < arity; a++)
                {
                    if (a > 0)
                    {
                        result.Append(',');
                    }

                    result.Append(typeArguments[next++]);
                }

                result.Append('}');
            }

            return result.ToString();
        }

        /// <summary>Splits <c>Ns.Outer`1.Inner</c> into the namespace prefix (with its dot) and the nesting levels.</summary>
        private string[] SplitLevels(string typeName, out string prefix)
        {
            int nestingDepth = nestedDepth.TryGetValue(typeName, out int d) ? d : 0;
            string[] parts = typeName.Split('.');
            int levelCount = nestingDepth + 1;
            prefix = parts.Length > levelCount ? string.Join(".", parts, 0, parts.Length - levelCount) + "." : string.Empty;
            return parts[(parts.Length - levelCount)..];
        }

        /// <summary>How many enclosing types each named type has (the namespace has dots too; the levels are told apart here).</summary>
        private static Dictionary<string, int> BuildNestingDepths(MetadataReader reader)
        {
            var depths = new Dictionary<string, int>(StringComparer.Ordinal);
            foreach (TypeDefinitionHandle h in reader.TypeDefinitions)
            {
                int depth = 0;
                for (TypeDefinitionHandle t = reader.GetTypeDefinition(h).GetDeclaringType(); !t.IsNil; t = reader.GetTypeDefinition(t).GetDeclaringType())
                {
                    depth++;
                }

                depths[TypeDefinitionName(reader, h)] = depth;
            }

            foreach (TypeReferenceHandle h in reader.TypeReferences)
            {
                int depth = 0;
                EntityHandle scope = reader.GetTypeReference(h).ResolutionScope;
                while (scope.Kind == HandleKind.TypeReference)
                {
                    depth++;
                    scope = reader.GetTypeReference((TypeReferenceHandle)scope).ResolutionScope;
                }

                depths[TypeReferenceName(reader, h)] = depth;
            }

            return depths;
        }

        private static string TypeReferenceName(MetadataReader reader, TypeReferenceHandle handle)
        {
            TypeReference type = reader.GetTypeReference(handle);
            string name = reader.GetString(type.Name);
            if (type.ResolutionScope.Kind == HandleKind.TypeReference)
            {
                return TypeReferenceName(reader, (TypeReferenceHandle)type.ResolutionScope) + "." + name;
            }

            string ns = reader.GetString(type.Namespace);
            return ns.Length == 0 ? name : ns + "." + name;
        }
    }
}
