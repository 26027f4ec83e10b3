#if NETSTANDARD2_1
namespace System.Runtime.CompilerServices
{
    /// <summary>Lets netstandard2.1 compile <c>init</c> accessors.</summary>
    internal static class IsExternalInit
    {
    }
}
#endif
