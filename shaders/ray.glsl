struct Ray {
    vec3 origin;
    vec3 direction; // unit length
};
