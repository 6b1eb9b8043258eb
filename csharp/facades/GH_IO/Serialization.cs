// COMPILE-TIME FACADE of GH_IO (never shipped): only the members Lamella.Grasshopper uses.
namespace GH_IO.Serialization
{
    public interface GH_IWriter
    {
        void SetByteArray(string item_name, byte[] item_value);
    }

    public interface GH_IReader
    {
        bool ItemExists(string name);
        byte[] GetByteArray(string name);
    }
}
