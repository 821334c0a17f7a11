using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Xml.Linq;
using AcDream.Core.Physics.World;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The XML documentation shipped next to AcDream.Core.dll (and in the package) documents the public surface only:
/// build/DocFilter drops what the compiler writes for private and internal members and for internal types, which made
/// internals (<c>PhysicsObj.RemovedFromWorld</c>, <c>Frame.M33</c>) look public to a reader of the XML.
/// </summary>
public sealed class XmlDocumentationTests
{
    private static readonly Assembly Library = typeof(PhysicsWorld).Assembly;

    private static List<string> MemberIds()
    {
        string xml = Path.ChangeExtension(Library.Location, ".xml");
        Assert.True(File.Exists(xml), $"{xml} missing");
        return XDocument.Load(xml).Descendants("member").Select(m => (string?)m.Attribute("name") ?? string.Empty).ToList();
    }

    [Fact]
    public void EveryDocumentedMember_IsPublicOrProtected_OnAVisibleType()
    {
        var wrong = new List<string>();
        foreach (string id in MemberIds())
        {
            if (!Resolves(id))
            {
                wrong.Add(id);
            }
        }

        Assert.True(wrong.Count == 0, "documented but not public surface:\n" + string.Join("\n", wrong));
    }

    [Fact]
    public void TheInternalsTheXmlOnceShowed_AreAbsent()
    {
        List<string> ids = MemberIds();
        foreach (string member in new[] { "AcDream.Core.Physics.Objects.PhysicsObj.RemovedFromWorld", "AcDream.Core.Physics.Spatial.Frame.M33" })
        {
            foreach (string kind in new[] { "P:", "F:", "M:" })
            {
                string id = kind + member;
                Assert.DoesNotContain(ids, i => i == id || i.StartsWith(id + "(", StringComparison.Ordinal));
            }
        }
    }

    [Fact]
    public void TypeEntries_AreTheExportedTypes()
    {
        // Every exported type has its summary (DocumentationTests), so the T: entries are exactly the exported types.
        int typeEntries = MemberIds().Count(i => i.StartsWith("T:", StringComparison.Ordinal));
        Assert.Equal(Library.GetExportedTypes().Length, typeEntries);
    }

    /// <summary>The ID names a visible type, or a public or protected member (of the ID's kind) of a visible type.</summary>
    private static bool Resolves(string id)
    {
        if (id.Length < 3 || id[1] != ':')
        {
            return false;
        }

        char kind = id[0];
        string name = id[2..];
        if (kind == 'T')
        {
            Type? type = FindType(name);
            return type is not null && IsVisible(type);
        }

        // Strip the parameters, a conversion's return type and a generic method's arity.
        int paren = name.IndexOf('(', StringComparison.Ordinal);
        if (paren >= 0)
        {
            name = name[..paren];
        }

        int tilde = name.IndexOf('~', StringComparison.Ordinal);
        if (tilde >= 0)
        {
            name = name[..tilde];
        }

        int arity = name.IndexOf("``", StringComparison.Ordinal);
        if (arity >= 0)
        {
            name = name[..arity];
        }

        int dot = name.LastIndexOf('.');
        if (dot < 0)
        {
            return false;
        }

        Type? owner = FindType(name[..dot]);
        if (owner is null || !IsVisible(owner))
        {
            return false;
        }

        string memberName = name[(dot + 1)..].Replace('#', '.');
        const BindingFlags all = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
        return owner.GetMember(memberName, all).Any(m => kind switch
        {
            'M' => m is MethodBase method && IsPublicOrProtected(method),
            'P' => m is PropertyInfo property && property.GetAccessors(nonPublic: true).Any(IsPublicOrProtected),
            'F' => m is FieldInfo field && (field.IsPublic || field.IsFamily || field.IsFamilyOrAssembly),
            'E' => m is EventInfo ev && ev.AddMethod is { } add && IsPublicOrProtected(add),
            _ => false,
        });
    }

    private static bool IsPublicOrProtected(MethodBase method) => method.IsPublic || method.IsFamily || method.IsFamilyOrAssembly;

    private static bool IsVisible(Type type) =>
        (type.IsPublic || type.IsNestedPublic || type.IsNestedFamily || type.IsNestedFamORAssem)
        && (type.DeclaringType is null || IsVisible(type.DeclaringType));

    /// <summary>A documentation ID's type name (nesting written with <c>.</c>, as a namespace is): tries <c>+</c> from the right.</summary>
    private static Type? FindType(string docName)
    {
        string[] parts = docName.Split('.');
        for (int nested = 0; nested < parts.Length; nested++)
        {
            string outer = string.Join(".", parts[..(parts.Length - nested)]);
            string inner = string.Join("+", parts[(parts.Length - nested)..]);
            Type? type = Library.GetType(nested == 0 ? outer : outer + "+" + inner);
            if (type is not null)
            {
                return type;
            }
        }

        return null;
    }
}
