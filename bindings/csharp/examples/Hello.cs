// Hello, the C# walkthrough: the C API's hello.c, in the binding's names.
// Two bunnies, one static and one held as a tool 14 cm along x; one
// deterministic step; the contacts and the force on the tool; then the same
// scene on Proxima's threads, with the built-in scripted device and then with
// the streamed device a game uses.
//
//   mono hello.exe path/to/bunny.obj
using System;
using System.Threading;
using Proxima;

static class Hello
{
    static int Main(string[] args)
    {
        if (args.Length != 1)
        {
            Console.Error.WriteLine("usage: hello.exe MESH (an OBJ, glTF or GLB file)");
            return 2;
        }
        Console.WriteLine("Proxima " + Proxima.Version.Library);
        try
        {
            // A world is IDisposable: dispose it on the thread that created it.
            using (var world = new World(new WorldSettings { Method = Method.Precise, Cutoff = 0.005, Force = ForcePreset.Hard }))
            {
                Mesh bunny = world.LoadMesh(args[0]);
                MeshInfo info = bunny.Info;
                Console.WriteLine("mesh: {0} triangles, {1} vertices", info.TriangleCount, info.VertexCount);

                Body rock = world.CreateBody(bunny, BodyType.Static, Pose.Identity);
                Body tool = world.CreateBody(bunny, BodyType.Tool, new Pose(new Vec3(0.14, 0, 0), Quat.Identity));

                world.Step();
                Contact[] contacts = tool.GetContacts();
                Console.WriteLine("{0} contact(s):", contacts.Length);
                foreach (Contact c in contacts)
                    Console.WriteLine("  tool triangle {0} ({1}) - {2} triangle {3} ({4}): {5:F6} m",
                                      c.TriangleTool, c.FeatureTool, c.Other == rock ? "rock" : "?",
                                      c.TriangleOther, c.FeatureOther, c.Distance);
                Wrench wrench = tool.GetWrench();
                Console.WriteLine("force {0} N, torque {1} N m{2}", wrench.Force, wrench.Torque,
                                  wrench.Clipped ? " (clipped)" : "");

                // Closer, where the surfaces cross: the intersection polylines.
                tool.Pose = new Pose(new Vec3(0.12, 0, 0), Quat.Identity);
                world.Step();
                Polyline[] lines = tool.GetIntersections();
                Console.WriteLine("at x = 0.12: {0} contacts, {1} intersection polyline(s)",
                                  tool.GetContacts().Length, lines.Length);

                // The threads: the scripted device moves the tool in, the haptic
                // loop renders the force at 1 kHz, this thread only reads.
                tool.Pose = new Pose(new Vec3(0.14, 0, 0), Quat.Identity);
                ScriptedDevice device = world.CreateScriptedDevice(
                    new[] { new Pose(new Vec3(0.16, 0, 0), Quat.Identity), new Pose(new Vec3(0.139, 0, 0), Quat.Identity) },
                    0.3, false);
                tool.SetDevice(device);
                world.StartThreads(ThreadSettings.Default);
                Thread.Sleep(500);
                world.StopThreads();
                ThreadStats haptic = world.GetThreadStats(ThreadRole.Haptic);
                ScriptedDeviceRecord record = device.Record;
                Console.WriteLine("threads: haptic loop at {0:F0} Hz, {1} poses read, largest force {2:F4} N",
                                  haptic.AchievedRate, record.Reads, record.MaxForce);

                // How a game drives the tool: push its pose once a frame (here 100 Hz)
                // to a streamed device; the haptic loop interpolates at 1 kHz, and
                // what it rendered is read back from any thread.
                StreamDevice hand = world.CreateStreamDevice();
                tool.SetDevice(hand);
                world.StartThreads(ThreadSettings.Default);
                double felt = 0;
                for (int frame = 0; frame <= 30; ++frame)
                {
                    hand.PushPose(new Pose(new Vec3(0.16 - 0.021 * frame / 30, 0, 0), Quat.Identity));
                    felt = Math.Max(felt, hand.GetWrench().Force.Length);
                    Thread.Sleep(10);
                }
                world.StopThreads();
                StreamDeviceStats stream = hand.Stats;
                Console.WriteLine("streamed: {0} frames pushed, {1} haptic ticks rendered them, largest force read back {2:F4} N",
                                  stream.SamplesPushed, stream.Reads, felt);
                return contacts.Length > 0 && record.Reads > 0 && record.AllFinite && stream.Reads > 0 ? 0 : 1;
            }
        }
        catch (ProximaException e)
        {
            Console.Error.WriteLine(e.Message);
            return 1;
        }
    }
}
