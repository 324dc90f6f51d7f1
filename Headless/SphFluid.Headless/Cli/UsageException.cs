using System;

namespace SphFluid.Headless.Cli;

/// <summary>A command-line mistake; the message names the argument and what it accepts (exit code 2).</summary>
public sealed class UsageException(string message) : Exception(message);
