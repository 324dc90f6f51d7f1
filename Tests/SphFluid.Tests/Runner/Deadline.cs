using System;
using System.Threading.Tasks;
using NUnit.Framework;

namespace SphFluid.Tests.Runner
{
    /// <summary>
    /// Runs work that used to hang (a parent cycle, a FIFO, a quadratic parse) on its own thread and fails the test
    /// when it is not done in time, so a regression shows as a failure instead of a stuck CI run.
    /// </summary>
    static class Deadline
    {
        public static T Within<T>(double seconds, Func<T> work, string what)
        {
            var task = Task.Factory.StartNew(work, TaskCreationOptions.LongRunning);
            Assert.That(task.Wait(TimeSpan.FromSeconds(seconds)), Is.True, $"{what} did not finish within {seconds} s");
            return task.Result;
        }

        /// <summary>The exception <paramref name="work"/> throws, or null; to assert on outside the worker thread.</summary>
        public static Exception? Thrown(Action work)
        {
            try
            {
                work();
                return null;
            }
            catch (Exception e)
            {
                return e;
            }
        }
    }
}
