using NUnit.Framework;

namespace SphFluid.Tests
{
    /// <summary>
    /// The Unity-file readers (and System.Xml) answer "not there" with null. A test that needs the thing fails here,
    /// naming what was missing, instead of with a NullReferenceException further on.
    /// </summary>
    static class Found
    {
        public static T OrFail<T>(this T? value, string what) where T : class =>
            value ?? throw new AssertionException(what + " not found");
    }
}
