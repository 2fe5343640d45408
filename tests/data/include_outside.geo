// A .geo that reads a file outside its folder: refused.
Include "../../meshes/channel.geo";
