// The cost of World.Step + Body.GetContacts from C#, for docs/csharp.md; its
// C twin is step_bench.c. Both run the same scene and loop and print one CSV
// row per case: language, case, iterations, ns per iteration.
//
//   mono step_bench.exe BUNNY.obj [iterations]
//
// Cases: "unchanged" steps a scene whose poses did not change (the step skips
// the search, so the call itself and the copy of the contacts dominate);
// "moving" moves the tool by 1 um each iteration (a global search per step).
using System;
using System.Diagnostics;
using Proxima;

static class StepBench
{
    static int Main(string[] args)
    {
        if (args.Length < 1)
        {
            Console.Error.WriteLine("usage: step_bench.exe MESH [iterations]");
            return 2;
        }
        int iterations = args.Length > 1 ? int.Parse(args[1]) : 20000;
        using (var world = new World())
        {
            Mesh bunny = world.LoadMesh(args[0]);
            world.CreateBody(bunny, BodyType.Static, Pose.Identity);
            var near = new Pose(new Vec3(0.135, 0.002, 0), new Quat(0.999, 0, 0.04, 0));
            Body tool = world.CreateBody(bunny, BodyType.Tool, near);
            var buffer = new Contact[64];
            world.Step();
            int contacts = tool.GetContacts(buffer);

            Console.WriteLine("language,case,iterations,contacts,ns_per_iteration");
            for (int i = 0; i < 1000; ++i)
            {
                world.Step();
                tool.GetContacts(buffer);
            }
            var clock = Stopwatch.StartNew();
            for (int i = 0; i < iterations; ++i)
            {
                world.Step();
                tool.GetContacts(buffer);
            }
            Console.WriteLine("csharp,unchanged,{0},{1},{2:F1}", iterations, contacts,
                              clock.Elapsed.TotalMilliseconds * 1e6 / iterations);

            int moving = Math.Max(1, iterations / 100);
            clock.Restart();
            for (int i = 0; i < moving; ++i)
            {
                Pose p = near;
                p.Position.X += 1e-6 * (i % 2);
                tool.Pose = p;
                world.Step();
                tool.GetContacts(buffer);
            }
            Console.WriteLine("csharp,moving,{0},{1},{2:F1}", moving, contacts,
                              clock.Elapsed.TotalMilliseconds * 1e6 / moving);
        }
        return 0;
    }
}
