#version 330 core
// World height in metres, into a 32-bit float target (the nearest surface to the camera above wins).
in float vHeight;
out vec4 fragColour;
void main()
{
    fragColour = vec4(vHeight, 0.0, 0.0, 1.0);
}
