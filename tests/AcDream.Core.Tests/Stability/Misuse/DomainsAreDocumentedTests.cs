using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Reflection;
using System.Xml.Linq;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using Xunit;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// Every public input of the misuse suite's catalog documents its valid domain: a member that takes a value with a bad class
/// (a float, double, vector, position, frame, sweep result, target report or sphere) names the refusal in an
/// <c>&lt;exception&gt;</c> tag of its XML doc, states the domain in the <c>&lt;param&gt;</c> of each such parameter, or
/// states it in a remark of the member or (for a type of pure queries) of its type.
/// </summary>
public class DomainsAreDocumentedTests
{
    private static readonly HashSet<Type> ValueTypes =
    [
        typeof(float), typeof(double), typeof(Vector3), typeof(Position), typeof(Frame), typeof(TransitionResult),
        typeof(TargetInfo), typeof(Sphere),
    ];

    private static string DocId(MethodInfo m)
    {
        static string TypeId(Type t) =>
            t.IsByRef ? TypeId(t.GetElementType()!) + "@"
            : t.IsGenericType ? t.GetGenericTypeDefinition().FullName![..t.GetGenericTypeDefinition().FullName!.IndexOf('`')]
                                + "{" + string.Join(",", t.GetGenericArguments().Select(TypeId)) + "}"
            : t.FullName!.Replace('+', '.');
        ParameterInfo[] ps = m.GetParameters();
        string args = ps.Length == 0 ? "" : "(" + string.Join(",", ps.Select(p => TypeId(p.ParameterType))) + ")";
        return "M:" + m.DeclaringType!.FullName!.Replace('+', '.') + "." + m.Name + args;
    }

    // A <remarks> of the member (or of its type, for a type of pure queries) that states the valid domain.
    private static bool StatesDomain(XElement doc) =>
        doc.Element("remarks") is { } r && r.Value.Contains("domain", StringComparison.OrdinalIgnoreCase);

    [Fact]
    public void EveryValueInputOfTheCatalog_DocumentsItsDomain()
    {
        string xml = Path.ChangeExtension(typeof(PhysicsWorld).Assembly.Location, ".xml");
        Dictionary<string, XElement> docs = XDocument.Load(xml).Descendants("member")
            .ToDictionary(e => (string)e.Attribute("name")!, e => e);
        var silent = new List<string>();
        foreach (MethodInfo m in MutatorCatalog.Discover(new MisuseScene()).Select(x => x.Method).Distinct())
        {
            string name = MutatorCatalog.Name(m);
            ParameterInfo[] valueParams = m.GetParameters()
                .Where(p => ValueTypes.Contains(MutatorCatalog.ParamType(p)) || Nullable.GetUnderlyingType(MutatorCatalog.ParamType(p)) is not null)
                .ToArray();
            if (valueParams.Length == 0 || MutatorCatalog.Excluded.ContainsKey(name))
            {
                continue;
            }

            // A property setter is documented on its property; an interface implementation may inherit its doc.
            string id = m.IsSpecialName && m.Name.StartsWith("set_", StringComparison.Ordinal)
                ? "P:" + m.DeclaringType!.FullName!.Replace('+', '.') + "." + m.Name[4..]
                : DocId(m);
            if (!docs.TryGetValue(id, out XElement? doc))
            {
                silent.Add(name + " (no XML doc " + id + ")");
                continue;
            }

            bool refusal = doc.Elements("exception").Any();
            bool paramsStated = valueParams.All(p => doc.Elements("param").Any(e => (string)e.Attribute("name")! == p.Name
                && e.Value.Trim().Length > 0));
            bool remarks = StatesDomain(doc) || (docs.TryGetValue("T:" + m.DeclaringType!.FullName!.Replace('+', '.'), out XElement? td)
                && StatesDomain(td));
            if (!refusal && !paramsStated && !remarks)
            {
                silent.Add(name);
            }
        }

        Assert.True(silent.Count == 0, "silent about their domain:\n" + string.Join("\n", silent));
    }
}
