using System.Runtime.CompilerServices;

// The PlayMode tests feed made-up diagnostics to Fluid.CheckHealth: a real blow-up cannot be ordered on demand.
[assembly: InternalsVisibleTo("SphFluid.Tests.PlayMode")]
