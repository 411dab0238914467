// OptionInfo: one row of the library's option table
// (onetip/sensor_option_table.hpp), read through the C ABI's introspection
// (onetip_option_count, onetip_option_describe). SensorOptions carries one
// field or property per row, named as the row in PascalCase (queue_capacity:
// QueueCapacity); the C# tests check that they match the table exactly.
using System;
using Onetip.Interop;

namespace Onetip
{
    public enum OptionType { Integer = 0, Real = 1, Flag = 2, Choice = 3, Axes = 4 }

    public sealed class OptionInfo
    {
        public string Name { get; private set; }       // the key: onetip_options field, file key
        public OptionType Type { get; private set; }
        public int Count { get; private set; }         // values: 1, or 6 for Axes (dx, dy, dz, yaw, pitch, roll)
        public double Min { get; private set; }        // closed range of every value
        public double Max { get; private set; }
        public double[] Default { get; private set; }  // Count values
        public string Unit { get; private set; }       // "" when none; "mm|deg": mm for dx..dz, deg for yaw..roll
        public string[] Choices { get; private set; }  // Choice: the names in value order
        public string Doc { get; private set; }

        /// <summary>The table's rows, in the order of the options file.</summary>
        public static OptionInfo[] Table()
        {
            Errors.RequireMinorVersion("the option table");
            int n = NativeMethods.onetip_option_count();
            var rows = new OptionInfo[n];
            for (int i = 0; i < n; ++i) {
                NativeOptionInfo row;
                NativeError e;
                Errors.Check(NativeMethods.onetip_option_describe(NativeMethods.AbiVersion, i, out row, out e), ref e);
                var values = new double[row.Count];
                Array.Copy(row.DefaultValue, values, row.Count);
                rows[i] = new OptionInfo {
                    Name = row.Name, Type = (OptionType)row.Type, Count = row.Count, Min = row.Min, Max = row.Max,
                    Default = values, Unit = row.Unit, Doc = row.Doc,
                    Choices = row.Choices.Length == 0 ? new string[0] : row.Choices.Split(' ')
                };
            }
            return rows;
        }
    }
}
