// COMPILE-TIME FACADE of GH_IO (never shipped): only the members Lamella.Grasshopper uses.
namespace GH_IO.Serialization
{
    public interface GH_IWriter
    {
        void SetByteArray(string item_name, byte[] item_value);
        void SetString(string item_name, string item_value);
        void SetDouble(string item_name, double item_value);
    }

    public interface GH_IReader
    {
        bool ItemExists(string name);
        byte[] GetByteArray(string name);
        string GetString(string name);
        double GetDouble(string name);
    }
}
