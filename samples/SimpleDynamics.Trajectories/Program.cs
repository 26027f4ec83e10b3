namespace SimpleDynamics.Trajectories;

public static class Program
{
    public static int Main(string[] args) => 0;
}
