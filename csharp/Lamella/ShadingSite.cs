using System;
using System.Runtime.InteropServices;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>What a vertex's strips do with the light (<c>LML_SHADING_*</c>, paper Sec. 6).</summary>
    public enum ShadingLabel : uint
    {
        /// <summary>Block the light of the block region (E_block, Eq. 26).</summary>
        Block = 0,
        /// <summary>Let the light of the pass region through (E_light, Eq. 27).</summary>
        Pass = 1,
        /// <summary>Transition: fairness and gradient terms only.</summary>
        Free = 2,
    }

    /// <summary>
    /// Where the building stands, how the model is oriented and when the shading is for (<c>LmlShadingSite</c>); start
    /// from <see cref="Default"/>. Angles in degrees, hours 0–24; the block region R_l comes from the dates and hours
    /// (or, with <see cref="DirectRegion"/> 1, from the δ and γ intervals, Eq. 24).
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct ShadingSite
    {
        /// <summary>Geographic latitude, north positive, in [−90, 90].</summary>
        public double LatitudeDegrees;
        /// <summary>North in model coordinates (made horizontal), x, y, z.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] North;
        /// <summary>Up in model coordinates, x, y, z.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] Up;
        /// <summary>Longitude, east positive (with <see cref="ClockTime"/> 1).</summary>
        public double LongitudeDegrees;
        /// <summary>Time zone, hours east of UTC (with <see cref="ClockTime"/> 1).</summary>
        public double TimeZoneHours;
        /// <summary>Daily hours whose sun the block vertices block.</summary>
        public double FirstHour;
        public double LastHour;
        /// <summary>Daily hours whose sun the pass vertices let through.</summary>
        public double PassFirstHour;
        public double PassLastHour;
        /// <summary>The δ interval of a direct block region (with <see cref="DirectRegion"/> 1).</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] DeltaDegrees;
        /// <summary>The γ interval of a direct block region.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] GammaDegrees;
        /// <summary>Dates first month-day to last month-day, both included (may run over the new year).</summary>
        public uint FirstMonth;
        public uint FirstDay;
        public uint LastMonth;
        public uint LastDay;
        /// <summary>0: hours are true solar time; 1: clock time of the longitude and time zone.</summary>
        public uint ClockTime;
        /// <summary>0: the block region from the dates and hours; 1: from the δ and γ intervals.</summary>
        public uint DirectRegion;

        /// <summary>Latitude 47.4°, north +y, up +z, 1 June to 31 August, 10 to 16 h true solar time.</summary>
        public static ShadingSite Default()
        {
            ShadingSite site;
            Native.Check(NativeMethods.lml_shading_site_default(out site));
            return site;
        }

        /// <summary>The dates as month-day pairs.</summary>
        public ShadingSite WithDates(int firstMonth, int firstDay, int lastMonth, int lastDay)
        {
            ShadingSite site = this;
            site.FirstMonth = checked((uint)firstMonth);
            site.FirstDay = checked((uint)firstDay);
            site.LastMonth = checked((uint)lastMonth);
            site.LastDay = checked((uint)lastDay);
            return site;
        }

        /// <summary>The dates from text <c>MM-DD..MM-DD</c> (as the CLI's <c>--dates</c>).</summary>
        /// <exception cref="FormatException">Not of that form (the text is quoted).</exception>
        public ShadingSite WithDates(string text)
        {
            string[] ends = SplitRange(text);
            int[] first = MonthDay(ends[0], text), last = MonthDay(ends[1], text);
            return WithDates(first[0], first[1], last[0], last[1]);
        }

        /// <summary>The daily hours from text <c>H..H</c> (decimal hours, as the CLI's <c>--hours</c>), for blocking and letting through.</summary>
        /// <exception cref="FormatException">Not of that form (the text is quoted).</exception>
        public ShadingSite WithHours(string text)
        {
            double[] hours = Hours(text);
            return WithHours(hours[0], hours[1]);
        }

        /// <summary>
        /// The daily hours whose sun the pass vertices let through, from text <c>H..H</c> (as the CLI's
        /// <c>--pass-hours</c>); the blocking hours stay. Call after <see cref="WithHours(string)"/>, which sets both.
        /// </summary>
        /// <exception cref="FormatException">Not of that form (the text is quoted).</exception>
        public ShadingSite WithPassHours(string text)
        {
            double[] hours = Hours(text);
            ShadingSite site = this;
            site.PassFirstHour = hours[0];
            site.PassLastHour = hours[1];
            return site;
        }

        private static double[] Hours(string text)
        {
            string[] ends = SplitRange(text);
            double first, last;
            var style = System.Globalization.NumberStyles.Float;
            var culture = System.Globalization.CultureInfo.InvariantCulture;
            if (!double.TryParse(ends[0].Trim(), style, culture, out first) || !double.TryParse(ends[1].Trim(), style, culture, out last))
                throw new FormatException("hours '" + text + "' are not H..H");
            return new[] { first, last };
        }

        private static string[] SplitRange(string text)
        {
            if (text == null) throw new ArgumentNullException(nameof(text));
            int at = text.IndexOf("..", StringComparison.Ordinal);
            if (at < 0) throw new FormatException("'" + text + "' is not a range A..B");
            return new[] { text.Substring(0, at), text.Substring(at + 2) };
        }

        private static int[] MonthDay(string part, string text)
        {
            string[] pieces = part.Trim().Split('-');
            int month, day;
            if (pieces.Length != 2 || !int.TryParse(pieces[0], out month) || !int.TryParse(pieces[1], out day) || month < 0 || day < 0)
                throw new FormatException("dates '" + text + "' are not MM-DD..MM-DD");
            return new[] { month, day };
        }

        /// <summary>The same daily hours for blocking and letting through.</summary>
        public ShadingSite WithHours(double first, double last)
        {
            ShadingSite site = this;
            site.FirstHour = site.PassFirstHour = first;
            site.LastHour = site.PassLastHour = last;
            return site;
        }
    }
}
