using System;

namespace Proxima
{
    /// <summary>A call into Proxima failed. Result says how; Message is the
    /// library's own, naming the offending argument.</summary>
    public class ProximaException : Exception
    {
        /// <summary>The proxResult of the failing call.</summary>
        public Result Result { get; }

        /// <summary>What proxGetLastError() said, naming the offending argument (or, for a
        /// failure the binding finds itself, such as a version mismatch, its own words).</summary>
        public string NativeMessage { get; }

        public ProximaException(Result result, string message)
            : base(ResultName(result) + ": " + message)
        {
            Result = result;
            NativeMessage = message;
        }

        /// <summary>The C name of a result ("PROX_ERROR_INVALID_HANDLE"). Any thread.</summary>
        public static string ResultName(Result result) => Native.Copy(Native.proxResultString(result));

        internal static ProximaException FromLastError(Result result) =>
            new ProximaException(result, Native.Copy(Native.proxGetLastError()));
    }
}
