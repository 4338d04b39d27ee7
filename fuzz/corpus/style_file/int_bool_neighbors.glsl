/* tlab style
name = "halo"
description = "a test style"
properties = ["color", "normal"]
neighbors = true
iterations = 12

[[parameter]]
name = "width"
type = "float"
default = 0.5
range = [0.0, 2.0]
description = "how wide"

[[parameter]]
name = "steps"
type = "int"
default = 3
range = [1, 8]
description = "how many"

[[parameter]]
name = "flip"
type = "bool"
default = false
description = "whether to flip"
*/
vec4 composite() { return vec4(width); }
