// Assembly attributes of Onetip.dll. The tests (OnetipTests.exe) call the
// raw entry points too, to check the C ABI's refusals (a wrong ABI version).
using System.Runtime.CompilerServices;

[assembly: InternalsVisibleTo("OnetipTests")]
