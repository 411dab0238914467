// SensorOptions against the option table as the C ABI describes it
// (OptionInfo.Table(): onetip_option_count, onetip_option_describe), label
// options: the public fields and properties of SensorOptions, named in
// PascalCase, are exactly the table's options; Default() holds the table's
// defaults; each member reads back through the keyed C accessor as the same
// value (so the class's layout matches onetip_options); values at min and max
// pass Validate() and values just outside (the next double, or the next
// integer) are refused with an Input error naming the option.
using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using System.Text.RegularExpressions;

namespace Onetip.Tests
{
    static class OptionsTests
    {
        public static void Run()
        {
            OptionInfo[] table = OptionInfo.Table();
            Check.That(table.Length > 0, "the option table has rows");
            var members = new Dictionary<string, MemberInfo>();
            foreach (var f in typeof(SensorOptions).GetFields(BindingFlags.Public | BindingFlags.Instance)) members[Snake(f.Name)] = f;
            foreach (var p in typeof(SensorOptions).GetProperties(BindingFlags.Public | BindingFlags.Instance)) members[Snake(p.Name)] = p;
            var names = table.Select(r => r.Name).ToList();
            Check.That(new HashSet<string>(members.Keys).SetEquals(names),
                       "SensorOptions members {" + string.Join(", ", members.Keys.OrderBy(n => n)) + "} are the table's {" +
                       string.Join(", ", names.OrderBy(n => n)) + "}");

            var defaults = SensorOptions.Default();
            foreach (OptionInfo row in table) {
                MemberInfo member;
                if (!members.TryGetValue(row.Name, out member)) continue;
                double[] values = Read(defaults, member);
                Check.That(values.SequenceEqual(row.Default), row.Name + ": Default() holds " + Text(values) +
                                                                  ", the table " + Text(row.Default));
                for (int k = 0; k < row.Count; ++k)
                    Check.That(defaults.Get(row.Name, k) == values[k], row.Name + "[" + k + "]: the C struct disagrees with the C# member");
                if (row.Type != OptionType.Flag) Bounds(row, member);
            }
            var keyed = SensorOptions.Default();
            keyed.Set("gain", -2.5, 3);
            keyed.Set("filter", (int)FilterKind.OneEuro);
            Check.That(keyed.Gain[3] == -2.5 && keyed.Filter == FilterKind.OneEuro, "Set writes the member of its key");
            string refused = ErrorOf(() => keyed.Set("queue_capacity", 65));
            Check.That(refused != null && refused.Contains("queue_capacity") && keyed.QueueCapacity == defaults.QueueCapacity,
                       "Set refuses a value outside the range and changes nothing: " + refused);
            Console.WriteLine(table.Length + " options checked against the table");
        }

        static void Bounds(OptionInfo row, MemberInfo member)
        {
            bool whole = row.Type != OptionType.Real && row.Type != OptionType.Axes;
            double below = whole ? row.Min - 1 : NextDown(row.Min), above = whole ? row.Max + 1 : NextUp(row.Max);
            for (int k = 0; k < row.Count; ++k) {
                foreach (double bound in new[] { row.Min, row.Max }) {
                    var o = SensorOptions.Default();
                    Write(o, member, k, bound);
                    Check.That(o.Get(row.Name, k) == bound, row.Name + "[" + k + "] = " + bound + " reaches the library");
                    string error = ErrorOf(o.Validate);
                    // release_mm at its max cannot be below press_mm: only the relation may refuse it.
                    Check.That(error == null || (error.Contains("must be below") && !error.Contains("must be in")),
                               row.Name + "[" + k + "] = " + bound + " (a bound) is refused: " + error);
                }
                foreach (double bad in new[] { below, above }) {
                    var o = SensorOptions.Default();
                    Write(o, member, k, bad);
                    string error = ErrorOf(o.Validate);
                    Check.That(error != null && error.Contains(row.Name) && error.Contains("must be in"),
                               row.Name + "[" + k + "] = " + bad.ToString("R") + " (outside) gave: " + (error ?? "no error"));
                }
            }
        }

        static string Snake(string pascal) { return Regex.Replace(pascal, "(?<!^)([A-Z])", "_$1").ToLowerInvariant(); }

        static double[] Read(SensorOptions o, MemberInfo member)
        {
            object value = member is FieldInfo ? ((FieldInfo)member).GetValue(o) : ((PropertyInfo)member).GetValue(o, null);
            if (value is double[]) return (double[])((double[])value).Clone();
            if (value is bool) return new[] { (bool)value ? 1.0 : 0.0 };
            if (value is FilterKind) return new[] { (double)(int)(FilterKind)value };
            return new[] { Convert.ToDouble(value) };
        }

        static void Write(SensorOptions o, MemberInfo member, int k, double v)
        {
            Type type = member is FieldInfo ? ((FieldInfo)member).FieldType : ((PropertyInfo)member).PropertyType;
            object value;
            if (type == typeof(double[])) {
                var values = Read(o, member);
                values[k] = v;
                value = values;
            } else if (type == typeof(FilterKind)) {
                value = (FilterKind)(int)v;
            } else if (type == typeof(int)) {
                value = (int)v;
            } else {
                value = v;
            }
            if (member is FieldInfo) ((FieldInfo)member).SetValue(o, value);
            else ((PropertyInfo)member).SetValue(o, value, null);
        }

        static string ErrorOf(Action action)
        {
            try {
                action();
                return null;
            } catch (OnetipException e) {
                return e.Kind == ErrorKind.Input ? e.Message : "kind " + e.Kind + ": " + e.Message;
            }
        }

        static double NextUp(double x)
        {
            if (x == 0) return double.Epsilon;
            long bits = BitConverter.DoubleToInt64Bits(x);
            return BitConverter.Int64BitsToDouble(x > 0 ? bits + 1 : bits - 1);
        }

        static double NextDown(double x) { return -NextUp(-x); }

        static string Text(double[] v) { return "[" + string.Join(", ", v.Select(x => x.ToString("R"))) + "]"; }
    }
}
