// Errors: every onetip_error the C ABI reports becomes an OnetipException
// with the library's one-line message and its kind (onetip_error_kind).
using System;
using Onetip.Interop;

namespace Onetip
{
    public enum ErrorKind
    {
        None = 0,
        NullArgument = 1,   // a required pointer was null
        InvalidHandle = 2,  // the handle was destroyed or never created
        Version = 3,        // this wrapper and the loaded library disagree on the ABI version
        Input = 4,          // bad input: a missing or malformed file, a bad source, an invalid option
        State = 5,          // not valid now (start twice, stop from inside a callback, ...)
        Internal = 6        // an unexpected failure inside the library (a bug)
    }

    public class OnetipException : Exception
    {
        public OnetipException(ErrorKind kind, string message) : base(message) { Kind = kind; }
        public ErrorKind Kind { get; private set; }
    }

    internal static class Errors
    {
        internal static void Check(int code, ref NativeError error)
        {
            if (code == 0) return;
            var kind = Enum.IsDefined(typeof(ErrorKind), code) ? (ErrorKind)code : ErrorKind.Internal;
            var message = string.IsNullOrEmpty(error.Message) ? "onetip: error " + code : error.Message;
            throw new OnetipException(kind, message);
        }

        /// <summary>Throws OnetipException (kind Version) when the loaded library lacks the
        /// C ABI minor version this wrapper calls (NativeMethods.AbiMinorVersion); `what` names the feature.</summary>
        internal static void RequireMinorVersion(string what)
        {
            uint minor = NativeMethods.onetip_abi_minor_version();
            if (minor < NativeMethods.AbiMinorVersion)
                throw new OnetipException(ErrorKind.Version, what + " needs C ABI minor version " +
                                          NativeMethods.AbiMinorVersion + ", the library has " + minor);
        }
    }
}
