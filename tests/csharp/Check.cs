// Check: a minimal assertion helper for the C# binding tests (no test
// framework is available with Debian's Mono): each failed check is printed
// with what was expected, and the program's exit code is the failure count.
using System;

namespace Onetip.Tests
{
    static class Check
    {
        public static int Failures;

        public static void That(bool condition, string what)
        {
            if (condition) return;
            ++Failures;
            Console.Error.WriteLine("FAILED: " + what);
        }

        public static void Near(double actual, double expected, double tolerance, string what)
        {
            That(Math.Abs(actual - expected) <= tolerance,
                 string.Format("{0}: {1:R} differs from {2:R} by more than {3}", what, actual, expected, tolerance));
        }

        /// <summary>Runs `action` and checks it throws T; returns the exception (or null).</summary>
        public static T Throws<T>(Action action, string what) where T : Exception
        {
            try {
                action();
            } catch (T e) {
                return e;
            } catch (Exception e) {
                That(false, what + ": threw " + e.GetType().Name + " (" + e.Message + "), not " + typeof(T).Name);
                return null;
            }
            That(false, what + ": did not throw " + typeof(T).Name);
            return null;
        }
    }
}
